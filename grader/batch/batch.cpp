// Grading a folder of submissions: layouts, outcomes, the gradebook. See batch.h.
//
// Batch notes
// -----------
// The input folder is the TA's, but the files in it are the students': a name becomes a path
// only through safeName(), and nothing here opens a submission's archives (a6_grade's intake does,
// with its limits). Canvas files are copied, never moved: the input folder stays as downloaded,
// so a re-run finds the same submissions.
//
// Keys (a submission's folder under the output folder) must come out the same on every run, or
// a resumed batch would not find its markers: the entries are read in sorted order and a
// duplicate key gets "-2", "-3", ... in that order.
#include "batch/batch.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <system_error>

#include "common/fnv1a.h"

namespace a6::grader::batch {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// A file larger than this is fingerprinted by its size and modification time, not its bytes.
constexpr std::uintmax_t kHashContentLimit = 64u << 20;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The archive extensions a6_grade's intake reads, longest first.
const std::vector<std::string> kArchiveExtensions = {".tar.gz", ".tar.bz2", ".tar.xz",
                                                     ".tgz",    ".zip",     ".tar"};

// The extension of an archive's name (lower case), or "".
std::string archiveExtension(const std::string& name) {
  const std::string l = lower(name);
  for (const std::string& ext : kArchiveExtensions) {
    if (l.size() > ext.size() && endsWith(l, ext)) return ext;
  }
  return "";
}

std::string describeEntry(const fs::file_status& st) {
  if (fs::is_symlink(st)) return "a symbolic link";
  if (fs::is_directory(st)) return "a folder";
  if (fs::is_regular_file(st)) return "a file";
  return "not a file or a folder";
}

// Gives every submission a unique key, in order: the first keeps its base, the next get -2, -3.
void assignKeys(std::vector<Submission>& subs, std::vector<std::string>& notes) {
  std::set<std::string> taken = {"gradebook.csv", "insights.html"};  // the output folder's own
  for (Submission& s : subs) {
    const std::string base = s.key;
    std::string key = base;
    for (int n = 2; taken.count(lower(key)) != 0; ++n) key = base + "-" + std::to_string(n);
    if (key != base) {
      notes.push_back("two submissions are named '" + base +
                      "': the second one's results are in '" + key + "/'");
    }
    taken.insert(lower(key));  // case-insensitive file systems hold one of Alice and alice
    s.key = key;
  }
  std::sort(subs.begin(), subs.end(),
            [](const Submission& a, const Submission& b) { return a.key < b.key; });
}

// ---- Gradescope -------------------------------------------------------------------------------

int indentOf(const std::string& line) {
  int n = 0;
  while (n < static_cast<int>(line.size()) && line[static_cast<std::size_t>(n)] == ' ') ++n;
  return n;
}

// A YAML scalar as Gradescope writes them: plain, 'single' ('' for a quote) or "double" (with
// backslash escapes); a trailing comment after a plain value is dropped.
std::string yamlScalar(std::string v) {
  while (!v.empty() && (v.back() == ' ' || v.back() == '\r' || v.back() == '\t')) v.pop_back();
  std::size_t start = v.find_first_not_of(' ');
  if (start == std::string::npos) return "";
  v = v.substr(start);
  if (v.size() >= 2 && v.front() == '\'' && v.back() == '\'') {
    std::string out;
    for (std::size_t i = 1; i + 1 < v.size(); ++i) {
      out += v[i];
      if (v[i] == '\'' && v[i + 1] == '\'') ++i;
    }
    return out;
  }
  if (v.size() >= 2 && v.front() == '"' && v.back() == '"') {
    std::string out;
    for (std::size_t i = 1; i + 1 < v.size(); ++i) {
      if (v[i] == '\\' && i + 2 < v.size()) {
        const char e = v[++i];
        out += e == 'n' ? '\n' : e == 't' ? '\t' : e;
      } else {
        out += v[i];
      }
    }
    return out;
  }
  if (const std::size_t hash = v.find(" #"); hash != std::string::npos) {
    v.resize(hash);
    while (!v.empty() && v.back() == ' ') v.pop_back();
  }
  if (v == "~" || v == "null") return "";
  return v;
}

// "key: value" -> (key, value) for keys such as ":name:" (Ruby symbols) or "name".
bool keyValue(const std::string& text, std::string& key, std::string& value) {
  std::size_t from = 0;
  if (!text.empty() && text[0] == ':') from = 1;
  const std::size_t colon = text.find(':', from);
  if (colon == std::string::npos) return false;
  if (colon + 1 < text.size() && text[colon + 1] != ' ') return false;
  key = text.substr(from, colon - from);
  value = colon + 1 < text.size() ? text.substr(colon + 1) : "";
  return true;
}

// ---- Canvas -----------------------------------------------------------------------------------

// "spring-1.cpp" -> ("spring.cpp", 1); "sub-2.tar.gz" -> ("sub.tar.gz", 2).
std::pair<std::string, int> withoutReupload(const std::string& name) {
  std::string ext;
  for (const std::string multi : {".tar.gz", ".tar.bz2", ".tar.xz"}) {
    if (name.size() > multi.size() && endsWith(lower(name), multi)) ext = multi;
  }
  if (ext.empty()) {
    const std::size_t dot = name.rfind('.');
    if (dot != std::string::npos && dot > 0) ext = name.substr(dot);
  }
  const std::string stem = name.substr(0, name.size() - ext.size());
  static const std::regex suffix("^(.+)-([0-9]{1,4})$");
  std::smatch m;
  if (std::regex_match(stem, m, suffix)) {
    return {m[1].str() + name.substr(stem.size()), std::stoi(m[2].str())};
  }
  return {name, 0};
}

// FNV-1a: enough to notice a changed file (this is not a defence against forgery: the input
// folder is the TA's).
struct Hash : Fnv1a {
  void addFile(const fs::path& file) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(file, ec);
    if (ec) {
      add("unreadable");
      return;
    }
    add(std::to_string(size));
    if (size > kHashContentLimit) {
      const auto time = fs::last_write_time(file, ec);
      add(std::to_string(time.time_since_epoch().count()));
      return;
    }
    std::ifstream in(file, std::ios::binary);
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
      addBytes(buffer, static_cast<std::size_t>(in.gcount()));
    }
  }
};

std::string number(double x) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(4) << std::round(x * 1e4) / 1e4;
  std::string s = out.str();
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

Json optionalNumber(const std::optional<double>& x) { return x ? Json(*x) : Json(nullptr); }

std::optional<double> numberOf(const Json& j) {
  if (j.is_number()) return j.get<double>();
  return std::nullopt;
}

}  // namespace

// ---- names ------------------------------------------------------------------------------------

const char* toString(Layout layout) {
  switch (layout) {
    case Layout::Plain:
      return "plain";
    case Layout::Gradescope:
      return "gradescope";
    case Layout::Canvas:
      return "canvas";
  }
  return "?";
}

std::optional<Layout> layoutNamed(const std::string& name) {
  for (const Layout l : {Layout::Plain, Layout::Gradescope, Layout::Canvas}) {
    if (lower(name) == toString(l)) return l;
  }
  return std::nullopt;
}

std::string safeName(const std::string& text) {
  std::string out;
  for (const unsigned char c : text) {
    const bool keep = std::isalnum(c) || c == '.' || c == '-' || c == '_';
    if (keep) {
      out += static_cast<char>(c);
    } else if (!out.empty() && out.back() != '_') {
      out += '_';  // spaces, accents (UTF-8 bytes), slashes: one '_' per run
    }
  }
  while (!out.empty() && (out.front() == '.' || out.front() == '_')) out.erase(0, 1);
  while (!out.empty() && out.back() == '_') out.pop_back();
  if (out.size() > 80) out.resize(80);
  return out.empty() ? "student" : out;
}

// ---- Gradescope -------------------------------------------------------------------------------

namespace {

// Reads a Gradescope submission_metadata.yml one line at a time (the shape: see
// parseGradescopeMetadata).
class MetadataReader {
 public:
  void read(std::string line) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const int indent = indentOf(line);
    const std::string body = line.substr(static_cast<std::size_t>(indent));
    if (body.empty() || body[0] == '#' || body == "---" || body[0] == '\t') return;
    if (indent == 0) {
      startSubmission(body);
      return;
    }
    if (people_ == nullptr) return;
    if (childIndent_ < 0) childIndent_ = indent;
    if (listIndent_ >= 0 && inSubmitters(indent, body)) return;
    std::string key, value;
    if (indent == childIndent_ && keyValue(body, key, value) && key == "submitters" &&
        yamlScalar(value).empty()) {
      listIndent_ = indent;  // (":submitters: []" names nobody)
      itemIndent_ = -1;
    }
  }

  std::map<std::string, std::vector<Person>> take() { return std::move(out_); }

 private:
  // A top-level key starts the next submission (a block scalar's text is always indented).
  void startSubmission(const std::string& body) {
    std::string key, value;
    people_ = nullptr;
    listIndent_ = -1;
    if (keyValue(body, key, value) && yamlScalar(value).empty()) {
      people_ = &out_[key];
      childIndent_ = -1;
    }
  }

  // Inside the :submitters: list: a line of it (true), or the first line after it (false).
  bool inSubmitters(int indent, const std::string& body) {
    const bool item = body.rfind("- ", 0) == 0;
    if (item && indent >= listIndent_ && (itemIndent_ < 0 || indent == itemIndent_)) {
      itemIndent_ = indent;
      people_->emplace_back();
      setField(body.substr(2));
      return true;
    }
    if (itemIndent_ >= 0 && indent == itemIndent_ + 2) {
      setField(body);
      return true;
    }
    if (indent > listIndent_) return true;  // deeper data of a submitter
    listIndent_ = -1;                       // the list ended
    return false;
  }

  void setField(const std::string& text) {
    std::string key, value;
    if (people_->empty() || !keyValue(text, key, value)) return;
    Person& p = people_->back();
    if (key == "name") p.name = yamlScalar(value);
    if (key == "email") p.email = yamlScalar(value);
    if (key == "sid") p.sid = yamlScalar(value);
  }

  std::map<std::string, std::vector<Person>> out_;
  std::vector<Person>* people_ = nullptr;  // the submission being read
  int childIndent_ = -1;                   // indentation of its keys
  int listIndent_ = -1;                    // >= 0 inside its :submitters: list: the key's indent
  int itemIndent_ = -1;                    // indentation of the list's "- "
};

}  // namespace

std::map<std::string, std::vector<Person>> parseGradescopeMetadata(const std::string& yaml) {
  // The shape read (Gradescope writes Ruby symbols as keys; other keys and deeper data skipped):
  //   submission_<id>:
  //     :submitters:
  //     - :name: Jane Doe
  //       :sid: '123'
  //       :email: jane@example.edu
  //     :created_at: ...
  MetadataReader reader;
  std::istringstream in(yaml);
  for (std::string line; std::getline(in, line);) reader.read(line);
  return reader.take();
}

// ---- Canvas -----------------------------------------------------------------------------------

std::optional<CanvasName> parseCanvasName(const std::string& fileName) {
  static const std::regex pattern("^([^_]+)_(?:([Ll][Aa][Tt][Ee])_)?([0-9]+)_([0-9]+)_(.+)$");
  std::smatch m;
  if (!std::regex_match(fileName, m, pattern)) return std::nullopt;
  CanvasName n;
  n.login = m[1].str();
  n.late = m[2].matched;
  n.userId = m[3].str();
  n.submissionId = m[4].str();
  std::tie(n.original, n.reupload) = withoutReupload(m[5].str());
  return n;
}

// ---- finding the submissions ------------------------------------------------------------------

namespace {

bool sameFile(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return !b.empty() && fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec);
}

// The folder of a Gradescope export: `input` itself, or its only sub-folder holding the
// metadata (the export zip unzips to assignment_<id>_export/).
fs::path gradescopeRoot(const fs::path& input, const fs::path& exclude) {
  std::error_code ec;
  if (fs::is_regular_file(input / "submission_metadata.yml", ec)) return input;
  fs::path found;
  int dirs = 0;
  for (fs::directory_iterator it(input, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!it->is_directory(ec) || it->is_symlink(ec) || name.empty() || name[0] == '.' ||
        name == "__MACOSX" || sameFile(it->path(), exclude)) {
      continue;
    }
    ++dirs;
    if (fs::is_regular_file(it->path() / "submission_metadata.yml", ec)) found = it->path();
  }
  return dirs == 1 ? found : fs::path();
}

std::vector<fs::directory_entry> sortedEntries(const fs::path& dir, std::string& error) {
  std::vector<fs::directory_entry> entries;
  std::error_code ec;
  fs::directory_iterator it(dir, ec);
  if (ec) {
    error = "cannot read " + dir.string() + ": " + ec.message();
    return entries;
  }
  for (fs::directory_iterator end; !ec && it != end; it.increment(ec)) entries.push_back(*it);
  if (ec) error = "cannot read " + dir.string() + ": " + ec.message();
  std::sort(entries.begin(), entries.end(),
            [](const fs::directory_entry& a, const fs::directory_entry& b) {
              return a.path().filename() < b.path().filename();
            });
  return entries;
}

// Entries no student made: hidden files (.DS_Store, .git) and the __MACOSX folder of a zip made
// on a Mac.
bool systemEntry(const std::string& name, std::vector<std::string>& notes) {
  if (name.empty() || name[0] == '.' || name == "__MACOSX") {
    notes.push_back(name + ": hidden or operating-system files, not a submission: skipped");
    return true;
  }
  return false;
}

void findPlain(const fs::path& input, const fs::path& exclude, Inventory& inv) {
  for (const fs::directory_entry& e : sortedEntries(input, inv.error)) {
    const std::string name = e.path().filename().string();
    std::error_code ec;
    const fs::file_status st = e.symlink_status(ec);
    if (sameFile(e.path(), exclude)) continue;  // the output folder
    if (systemEntry(name, inv.notes)) continue;
    Submission s;
    if (fs::is_directory(st)) {
      s.key = safeName(name);
      s.path = e.path();
      s.people.push_back({name, "", ""});
    } else if (fs::is_regular_file(st) && !archiveExtension(name).empty()) {
      const std::string stem = name.substr(0, name.size() - archiveExtension(name).size());
      s.key = safeName(stem);
      s.path = e.path();
      s.people.push_back({stem, "", ""});
    } else {
      inv.notes.push_back(name + ": " + describeEntry(st) +
                          ", neither a folder nor an archive (.zip .tar .tar.gz .tgz): skipped");
      continue;
    }
    inv.submissions.push_back(std::move(s));
  }
}

// The submission in export folder or archive `path` (named `id`), its people from the metadata
// (the folder's name when it names nobody), its key made of their names.
Submission gradescopeSubmission(const std::string& id, const fs::path& path,
                                const std::map<std::string, std::vector<Person>>& metadata) {
  Submission s;
  s.path = path;
  const auto found = metadata.find(id);
  if (found != metadata.end()) {
    for (const Person& p : found->second) {
      if (!p.name.empty() || !p.email.empty() || !p.sid.empty()) s.people.push_back(p);
    }
  } else {
    s.notes.push_back(id + " is not in submission_metadata.yml");
  }
  if (s.people.empty()) {
    s.people.push_back({id, "", ""});
    if (found != metadata.end()) s.notes.push_back(id + " has no submitter in the metadata");
  }
  std::string base;
  for (const Person& p : s.people) {
    const std::string who = !p.name.empty() ? p.name : !p.sid.empty() ? p.sid : p.email;
    base += (base.empty() ? "" : "-") + safeName(who);
  }
  s.key = safeName(base);
  if (s.people.size() > 1) {
    s.notes.push_back("a group submission of " + std::to_string(s.people.size()) +
                      " students: one gradebook row each");
  }
  return s;
}

// The submission id of an export entry (submission_<id>, a folder or an archive), or "" (noted)
// when it is none.
std::string gradescopeId(const fs::directory_entry& e, Inventory& inv) {
  const std::string name = e.path().filename().string();
  std::error_code ec;
  const fs::file_status st = e.symlink_status(ec);
  const bool folder = fs::is_directory(st);
  const bool archive = fs::is_regular_file(st) && !archiveExtension(name).empty();
  const std::string id =
      archive ? name.substr(0, name.size() - archiveExtension(name).size()) : name;
  if ((!folder && !archive) || id.rfind("submission_", 0) != 0) {
    inv.notes.push_back(name + ": " + describeEntry(st) +
                        ", not a submission_<id> folder of the export: skipped");
    return "";
  }
  return id;
}

void findGradescope(const fs::path& input, const fs::path& exclude, Inventory& inv) {
  const fs::path root = gradescopeRoot(input, exclude);
  if (root.empty()) {
    inv.error = "no submission_metadata.yml in " + input.string() +
                " (or in its only sub-folder): not a Gradescope export";
    return;
  }
  const auto metadata = parseGradescopeMetadata(readAll(root / "submission_metadata.yml"));
  if (metadata.empty()) {
    inv.notes.push_back(
        "submission_metadata.yml names no submission: the submitters' names are "
        "those of the folders");
  }
  std::set<std::string> seen;
  for (const fs::directory_entry& e : sortedEntries(root, inv.error)) {
    const std::string name = e.path().filename().string();
    if (name == "submission_metadata.yml" || sameFile(e.path(), exclude)) continue;
    if (systemEntry(name, inv.notes)) continue;
    const std::string id = gradescopeId(e, inv);
    if (id.empty()) continue;
    seen.insert(id);
    inv.submissions.push_back(gradescopeSubmission(id, e.path(), metadata));
  }
  for (const auto& [id, people] : metadata) {
    if (!seen.count(id)) {
      inv.notes.push_back(id + " is in submission_metadata.yml but has no folder: not graded");
    }
  }
}

void findCanvas(const fs::path& input, const fs::path& exclude, Inventory& inv) {
  struct File {
    fs::path path;
    CanvasName name;
  };
  std::map<std::pair<std::string, std::string>, std::vector<File>> byStudent;
  for (const fs::directory_entry& e : sortedEntries(input, inv.error)) {
    const std::string name = e.path().filename().string();
    std::error_code ec;
    const fs::file_status st = e.symlink_status(ec);
    if (sameFile(e.path(), exclude) || systemEntry(name, inv.notes)) continue;
    const auto parsed = fs::is_regular_file(st) ? parseCanvasName(name) : std::nullopt;
    if (!parsed) {
      inv.notes.push_back(name + ": " + describeEntry(st) +
                          (fs::is_regular_file(st)
                               ? ", not named <login>_<userid>_<submissionid>_<file> as Canvas "
                                 "names them: skipped"
                               : ", not a file of a Canvas download: skipped"));
      continue;
    }
    byStudent[{parsed->login, parsed->userId}].push_back({e.path(), *parsed});
  }
  for (auto& [who, files] : byStudent) {
    Submission s;
    s.key = safeName(who.first);
    s.people.push_back({who.first, "", who.second});
    // Several uploads under one name: the latest wins (Canvas's -N suffix, then the id).
    std::map<std::string, const File*> latest;
    auto later = [](const File& a, const File& b) {
      if (a.name.reupload != b.name.reupload) return a.name.reupload > b.name.reupload;
      if (a.name.submissionId.size() != b.name.submissionId.size())
        return a.name.submissionId.size() > b.name.submissionId.size();
      return a.name.submissionId > b.name.submissionId;
    };
    bool late = false;
    for (const File& f : files) {
      late = late || f.name.late;
      const File*& kept = latest[f.name.original];
      if (kept == nullptr || later(f, *kept)) {
        if (kept != nullptr) {
          s.notes.push_back(kept->path.filename().string() + " replaced by the later upload " +
                            f.path.filename().string());
        }
        kept = &f;
      } else {
        s.notes.push_back(f.path.filename().string() + " replaced by the later upload " +
                          kept->path.filename().string());
      }
    }
    for (const auto& [original, f] : latest) s.files.emplace_back(f->path, original);
    if (late) s.notes.push_back("submitted late");
    inv.submissions.push_back(std::move(s));
  }
}

}  // namespace

Layout detectLayout(const fs::path& input, const fs::path& exclude) {
  if (!gradescopeRoot(input, exclude).empty()) return Layout::Gradescope;
  std::string error;
  int canvas = 0, other = 0;
  for (const fs::directory_entry& e : sortedEntries(input, error)) {
    std::error_code ec;
    const fs::file_status st = e.symlink_status(ec);
    const std::string name = e.path().filename().string();
    if (name.empty() || name[0] == '.' || name == "__MACOSX" || sameFile(e.path(), exclude)) {
      continue;
    }
    if (fs::is_directory(st)) return Layout::Plain;  // Canvas downloads are flat
    if (fs::is_regular_file(st) && parseCanvasName(e.path().filename().string())) {
      ++canvas;
    } else {
      ++other;
    }
  }
  return canvas > 0 && canvas >= other ? Layout::Canvas : Layout::Plain;
}

Inventory findSubmissions(const fs::path& input, Layout layout, const fs::path& exclude) {
  Inventory inv;
  inv.layout = layout;
  std::error_code ec;
  if (!fs::is_directory(input, ec)) {
    inv.error = input.string() + " is not a folder";
    return inv;
  }
  switch (layout) {
    case Layout::Plain:
      findPlain(input, exclude, inv);
      break;
    case Layout::Gradescope:
      findGradescope(input, exclude, inv);
      break;
    case Layout::Canvas:
      findCanvas(input, exclude, inv);
      break;
  }
  assignKeys(inv.submissions, inv.notes);
  return inv;
}

std::string stage(Submission& submission, const fs::path& dir) {
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir, ec);
  if (ec) return "cannot create " + dir.string() + ": " + ec.message();
  for (const auto& [from, name] : submission.files) {
    // The name is the student's: only its last component, made safe, is used.
    const std::string target = safeName(fs::path(name).filename().string());
    fs::copy_file(from, dir / target, fs::copy_options::overwrite_existing, ec);
    if (ec)
      return "cannot copy " + from.string() + " to " + (dir / target).string() + ": " +
             ec.message();
  }
  // One archive uploaded alone is the submission itself (a6_grade does not open an archive
  // inside a folder).
  if (submission.files.size() == 1 && !archiveExtension(submission.files[0].second).empty()) {
    submission.path = dir / safeName(fs::path(submission.files[0].second).filename().string());
  } else {
    submission.path = dir;
  }
  return "";
}

std::string fingerprint(const Submission& submission, const std::string& options) {
  Hash h;
  h.add(options);
  std::error_code ec;
  if (!submission.files.empty()) {
    for (const auto& [from, name] : submission.files) {
      h.add(name);
      h.addFile(from);
    }
    return h.hex();
  }
  const fs::file_status st = fs::symlink_status(submission.path, ec);
  if (!fs::is_directory(st)) {
    h.add("file");
    h.addFile(submission.path);
    return h.hex();
  }
  std::vector<fs::path> entries;
  for (fs::recursive_directory_iterator it(submission.path, ec), end; !ec && it != end;
       it.increment(ec)) {
    entries.push_back(it->path());
  }
  std::sort(entries.begin(), entries.end());
  for (const fs::path& p : entries) {
    const fs::file_status s = fs::symlink_status(p, ec);
    h.add(p.lexically_relative(submission.path).string());
    if (fs::is_symlink(s)) {
      h.add("link " + fs::read_symlink(p, ec).string());
    } else if (fs::is_regular_file(s)) {
      h.add("file");
      h.addFile(p);
    } else {
      h.add(fs::is_directory(s) ? "dir" : "other");
    }
  }
  return h.hex();
}

// ---- outcomes ---------------------------------------------------------------------------------

namespace {

// extra_data.incidents as lines for a TA: "the code crashed 2 times", ...
std::string oneNumber(double n) {
  std::ostringstream out;
  out << n;
  return out.str();
}

std::vector<std::string> flagsOf(const Json& incidents) {
  std::vector<std::string> flags;
  auto add = [&](const char* key, const std::string& what) {
    const double n = incidents.is_object() ? numberOf(incidents.value(key, Json())).value_or(0) : 0;
    if (n > 0) flags.push_back(what + " " + oneNumber(n) + (n == 1 ? " time" : " times"));
  };
  add("crashes", "the code crashed");
  add("timeouts", "the code ran out of time");
  add("start_failures", "the program did not start");
  return flags;
}

}  // namespace

int taskOfTag(const std::string& tag) {
  const bool named = tag.size() == 5 && tag.rfind("task", 0) == 0 && tag[4] >= '1' &&
                     tag[4] <= '0' + static_cast<int>(kTasks);
  return named ? tag[4] - '0' : 0;
}

namespace {

// The task (1..kTasks) a test's tags name, 0 for none; and whether they say extra credit.
std::pair<int, bool> taskOfTags(const Json& tags) {
  int task = 0;
  bool extraCredit = false;
  for (const Json& tag : tags) {
    if (!tag.is_string()) continue;
    const std::string s = tag.get<std::string>();
    if (s == "extra_credit") extraCredit = true;
    if (const int t = taskOfTag(s); t > 0) task = t;
  }
  return {task, extraCredit};
}

// The points of the tests summed per task and as extra credit, and the maximum, into `o`
// (extra_data's own maximum and extra credit win when given).
void pointsOfTests(const Json& tests, const Json& extra, Outcome& o) {
  double max = 0, extraCredit = 0;
  std::array<double, kTasks> tasks{};
  for (const Json& t : tests) {
    const double score = t.value("score", 0.0);
    max += t.value("max_score", 0.0);
    const auto [task, isExtra] = taskOfTags(t.value("tags", Json::array()));
    if (isExtra) {
      extraCredit += score;
    } else if (task > 0) {
      tasks[static_cast<std::size_t>(task - 1)] += score;
    }
  }
  o.max = numberOf(extra.value("max_score", Json())).value_or(max);
  o.extraCredit = numberOf(extra.value("extra_credit", Json())).value_or(extraCredit);
  for (std::size_t i = 0; i < tasks.size(); ++i) o.tasks[i] = std::round(tasks[i] * 1e4) / 1e4;
}

// Which task files fell back to the starter, and why, from extra_data.build (file -> status):
// "no task file in the submission", "spring.cpp, forces.cpp compile error; ...", or "".
std::string brokenBuild(const Json& extra) {
  std::vector<std::pair<std::string, std::string>> byStatus;  // status -> its files, in order
  int missing = 0, files = 0;
  if (extra.contains("build") && extra["build"].is_object()) {
    for (const auto& [file, status] : extra["build"].items()) {
      const std::string s = status.is_string() ? status.get<std::string>() : status.dump();
      ++files;
      if (s == "compiled") continue;
      missing += s == "missing";
      auto it = std::find_if(byStatus.begin(), byStatus.end(),
                             [&](const auto& b) { return b.first == s; });
      if (it == byStatus.end()) it = byStatus.insert(byStatus.end(), {s, ""});
      it->second += (it->second.empty() ? "" : ", ") + file;
    }
  }
  if (missing > 0 && missing == files) return "no task file in the submission";
  std::string broken;
  for (const auto& [status, list] : byStatus) {
    broken += (broken.empty() ? "" : "; ") + list + " " + status;
  }
  return broken;
}

// The ids of extra_data.mistakes ([{"task": 1, "mistake": "t1_wrong_sign", ...}, ...]), or of a
// marker's list of ids.
std::vector<std::string> mistakesOf(const Json& list) {
  std::vector<std::string> ids;
  if (!list.is_array()) return ids;
  for (const Json& m : list) {
    const Json id = m.is_object() ? m.value("mistake", Json()) : m;
    if (id.is_string() && !id.get<std::string>().empty()) ids.push_back(id.get<std::string>());
  }
  return ids;
}

}  // namespace

Outcome outcomeOfResults(const std::string& resultsJson) {
  Outcome o;
  const Json r = Json::parse(resultsJson, nullptr, false);
  if (r.is_discarded() || !r.is_object() || !r.contains("score") || !r["score"].is_number() ||
      !r.contains("tests") || !r["tests"].is_array()) {
    o.reason = resultsJson.empty() ? "a6_grade wrote no results.json"
                                   : "a6_grade's results.json is not valid";
    return o;
  }
  const Json extra = r.value("extra_data", Json::object());
  // a6_grade's own errors (its placeholder from the start of a run says it did not finish).
  if (extra.contains("errors") && extra["errors"].is_array() && !extra["errors"].empty()) {
    o.reason = extra["errors"][0].is_string() ? extra["errors"][0].get<std::string>()
                                              : extra["errors"][0].dump();
    return o;
  }
  o.total = r["score"].get<double>();
  if (extra.contains("refused") && extra["refused"].is_string()) {
    o.status = kNotGraded;
    o.reason = extra["refused"].get<std::string>();
    o.max = numberOf(extra.value("max_score", Json()));
    return o;
  }
  o.flags = flagsOf(extra.value("incidents", Json::object()));
  o.mistakes = mistakesOf(extra.value("mistakes", Json::array()));
  pointsOfTests(r["tests"], extra, o);
  o.reason = brokenBuild(extra);
  o.status = o.reason.empty() ? kGraded : kBuildFailed;
  return o;
}

std::string markerJson(const std::string& fingerprint, const Outcome& o) {
  Json j;
  j["fingerprint"] = fingerprint;
  j["status"] = o.status;
  j["total"] = optionalNumber(o.total);
  j["max"] = optionalNumber(o.max);
  Json tasks = Json::array();
  for (const auto& t : o.tasks) tasks.push_back(optionalNumber(t));
  j["tasks"] = tasks;
  j["extra_credit"] = optionalNumber(o.extraCredit);
  j["seconds"] = std::round(o.seconds * 100) / 100;
  j["reason"] = o.reason;
  j["flags"] = o.flags;
  j["mistakes"] = o.mistakes;
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::optional<Outcome> outcomeOfMarker(const std::string& markerText,
                                       const std::string& fingerprint) {
  const Json j = Json::parse(markerText, nullptr, false);
  if (j.is_discarded() || !j.is_object() || j.value("fingerprint", "") != fingerprint ||
      !j.contains("status") || !j["status"].is_string()) {
    return std::nullopt;
  }
  Outcome o;
  o.status = j["status"].get<std::string>();
  o.total = numberOf(j.value("total", Json()));
  o.max = numberOf(j.value("max", Json()));
  const Json tasks = j.value("tasks", Json::array());
  for (std::size_t i = 0; i < o.tasks.size() && i < tasks.size(); ++i)
    o.tasks[i] = numberOf(tasks[i]);
  o.extraCredit = numberOf(j.value("extra_credit", Json()));
  o.seconds = numberOf(j.value("seconds", Json())).value_or(0);
  o.reason = j.value("reason", "");
  for (const Json& flag : j.value("flags", Json::array())) {
    if (flag.is_string()) o.flags.push_back(flag.get<std::string>());
  }
  o.mistakes = mistakesOf(j.value("mistakes", Json::array()));
  return o;
}

// ---- the gradebook and the summary ------------------------------------------------------------

std::string csvField(const std::string& text) {
  const bool quote = text.find_first_of(",\"\r\n") != std::string::npos ||
                     (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!quote) return text;
  std::string out = "\"";
  for (const char c : text) {
    out += c;
    if (c == '"') out += '"';
  }
  return out + "\"";
}

std::string gradebookCsv(const std::vector<std::pair<const Submission*, const Outcome*>>& graded) {
  std::string csv = "student,email,sid,total,max,";
  for (std::size_t t = 1; t <= kTasks; ++t) csv += "task" + std::to_string(t) + ",";
  csv += "extra_credit,status,seconds,mistakes\r\n";
  auto num = [](const std::optional<double>& x) { return x ? number(*x) : std::string(); };
  for (const auto& [s, o] : graded) {
    for (const Person& p : s->people) {
      csv += csvField(p.name) + "," + csvField(p.email) + "," + csvField(p.sid) + ",";
      csv += num(o->total) + "," + num(o->max) + ",";
      for (const auto& t : o->tasks) csv += num(t) + ",";
      csv += num(o->extraCredit) + "," + csvField(o->status) + ",";
      std::ostringstream seconds;
      seconds << std::fixed << std::setprecision(1) << o->seconds;
      std::string mistakes;
      for (const std::string& m : o->mistakes) mistakes += (mistakes.empty() ? "" : " ") + m;
      csv += seconds.str() + "," + csvField(mistakes) + "\r\n";
    }
  }
  return csv;
}

std::string mistakeCounts(const std::vector<const Outcome*>& outcomes) {
  std::map<std::string, int> count;
  for (const Outcome* o : outcomes) {
    for (const std::string& m : o->mistakes) ++count[m];
  }
  std::vector<std::pair<int, std::string>> ranked;
  for (const auto& [id, n] : count) ranked.emplace_back(-n, id);
  std::sort(ranked.begin(), ranked.end());
  std::ostringstream out;
  for (const auto& [minus, id] : ranked) {
    out << "    " << std::left << std::setw(40) << id << std::right << std::setw(5) << -minus
        << (minus == -1 ? " submission" : " submissions") << "\n";
  }
  return out.str();
}

std::string histogram(const std::vector<double>& totals) {
  if (totals.empty()) return "";
  std::map<int, int> bins;
  int top = 0;
  for (const double t : totals) {
    const int bin = std::max(0, static_cast<int>(std::floor(t / 10 + 1e-9)));
    ++bins[bin];
    top = std::max(top, bin);
  }
  int most = 0;
  for (const auto& [bin, n] : bins) most = std::max(most, n);
  const double scale = most > 50 ? 50.0 / most : 1.0;  // bars at most 50 wide
  std::ostringstream out;
  for (int b = 0; b <= top; ++b) {
    const int n = bins.count(b) ? bins[b] : 0;
    const std::string label = std::to_string(b * 10) + "-" + std::to_string(b * 10 + 9);
    const int width = n == 0 ? 0 : std::max(1, static_cast<int>(std::lround(n * scale)));
    out << "    " << std::setw(7) << label << " | "
        << std::string(static_cast<std::size_t>(width), '#')
        << (n > 0 ? " " + std::to_string(n) : "") << "\n";
  }
  return out.str();
}

std::string duration(double seconds) {
  const long s = std::max(0L, std::lround(seconds));
  char buf[32];
  if (s >= 3600) {
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  } else if (s >= 60) {
    std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%lds", s);
  }
  return buf;
}

}  // namespace a6::grader::batch
