// The layouts of an input folder: each submission found, named, staged and fingerprinted. See
// batch.h; outcomes and the gradebook are in batch.cpp.
//
// Notes: the files are the students', so a name becomes a path only through safeName(), and no
// archive is opened here (a6_grade's intake does, with its limits). Canvas files are copied, never
// moved, so a re-run finds the same submissions. Keys must be the same on every run, or a resume
// would not find its markers: entries are read sorted, and a duplicate key gets "-2", "-3", ...
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <regex>
#include <set>
#include <system_error>

#include "batch/batch.h"
#include "common/fnv1a.h"
#include "common/read_all.h"

namespace a6::grader::batch {

namespace {

namespace fs = std::filesystem;

// A file larger than this is fingerprinted by its size and modification time, not its bytes.
constexpr std::uintmax_t kHashContentLimit = 64u << 20;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The archive extensions a6_grade's intake reads, longest first.
const std::vector<std::string> kArchiveExtensions = {".tar.gz", ".tar.bz2", ".tar.xz",
                                                     ".tgz",    ".zip",     ".tar"};

// The extension of an archive's name (lower case), or "".
std::string archiveExtension(const std::string& name) {
  const std::string l = lower(name);
  for (const std::string& ext : kArchiveExtensions) {
    if (l.size() > ext.size() && l.compare(l.size() - ext.size(), ext.size(), ext) == 0) return ext;
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

// ---- Canvas -----------------------------------------------------------------------------------

// "spring-1.cpp" -> ("spring.cpp", 1); "sub-2.tar.gz" -> ("sub.tar.gz", 2).
std::pair<std::string, int> withoutReupload(const std::string& name) {
  std::string ext = archiveExtension(name);
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

// The value at a key Gradescope writes as a Ruby symbol (":name"), or at the plain key; a null
// node when neither is there.
YAML::Node at(const YAML::Node& map, const std::string& key) {
  if (!map.IsMap()) return YAML::Node();
  for (const std::string& k : {":" + key, key}) {
    if (const YAML::Node value = map[k]) return value;
  }
  return YAML::Node();
}

std::string scalarAt(const YAML::Node& map, const std::string& key) {
  const YAML::Node value = at(map, key);
  return value.IsScalar() ? value.Scalar() : "";
}

}  // namespace

std::map<std::string, std::vector<Person>> parseGradescopeMetadata(const std::string& yaml) {
  // The shape read (Gradescope writes Ruby symbols as keys; other keys are skipped):
  //   submission_<id>:
  //     :submitters:
  //     - :name: Jane Doe
  //       :sid: '123'
  //       :email: jane@example.edu
  //     :created_at: ...
  std::map<std::string, std::vector<Person>> out;
  try {
    const YAML::Node root = YAML::Load(yaml);
    if (!root.IsMap()) return out;
    for (const auto& submission : root) {
      if (!submission.first.IsScalar()) continue;
      if (!submission.second.IsMap() && !submission.second.IsNull()) continue;
      std::vector<Person>& people = out[submission.first.Scalar()];
      const YAML::Node submitters = at(submission.second, "submitters");
      if (!submitters.IsSequence()) continue;
      for (const YAML::Node& s : submitters) {
        people.push_back({scalarAt(s, "name"), scalarAt(s, "email"), scalarAt(s, "sid")});
      }
    }
  } catch (const YAML::Exception&) {
    return {};  // not YAML: no submission named (the caller says so)
  }
  return out;
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

// Entries no student made: hidden files (.DS_Store, .git), a Mac zip's __MACOSX folder.
bool isSystemName(const std::string& name) {
  return name.empty() || name[0] == '.' || name == "__MACOSX";
}

bool sameFile(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return !b.empty() && fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec);
}

std::vector<fs::directory_entry> sortedEntries(const fs::path& dir, std::string& error) {
  std::vector<fs::directory_entry> entries;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    entries.push_back(*it);
  }
  if (ec) error = "cannot read " + dir.string() + ": " + ec.message();
  std::sort(entries.begin(), entries.end(),
            [](const fs::directory_entry& a, const fs::directory_entry& b) {
              return a.path().filename() < b.path().filename();
            });
  return entries;
}

bool systemEntry(const std::string& name, std::vector<std::string>& notes) {
  if (isSystemName(name)) {
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
    const std::string ext = fs::is_regular_file(st) ? archiveExtension(name) : "";
    if (!fs::is_directory(st) && ext.empty()) {
      inv.notes.push_back(name + ": " + describeEntry(st) +
                          ", neither a folder nor an archive (.zip .tar .tar.gz .tgz): skipped");
      continue;
    }
    const std::string stem = name.substr(0, name.size() - ext.size());  // a folder: its name
    Submission s;
    s.key = safeName(stem);
    s.path = e.path();
    s.people.push_back({stem, "", ""});
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

// An export entry's submission id (submission_<id>, folder or archive), or "" (noted) if none.
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
      const bool newer = kept == nullptr || later(f, *kept);
      if (kept != nullptr) {
        const File& older = newer ? *kept : f;
        const File& upload = newer ? f : *kept;
        s.notes.push_back(older.path.filename().string() + " replaced by the later upload " +
                          upload.path.filename().string());
      }
      if (newer) kept = &f;
    }
    for (const auto& [original, f] : latest) s.files.emplace_back(f->path, original);
    if (late) s.notes.push_back("submitted late");
    inv.submissions.push_back(std::move(s));
  }
}

}  // namespace

fs::path gradescopeRoot(const fs::path& input, const fs::path& exclude) {
  std::error_code ec;
  if (fs::is_regular_file(input / "submission_metadata.yml", ec)) return input;
  fs::path found;
  int dirs = 0;
  for (fs::directory_iterator it(input, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (!it->is_directory(ec) || it->is_symlink(ec) || isSystemName(name) ||
        sameFile(it->path(), exclude)) {
      continue;
    }
    ++dirs;
    if (fs::is_regular_file(it->path() / "submission_metadata.yml", ec)) found = it->path();
  }
  return dirs == 1 ? found : fs::path();
}

Layout detectLayout(const fs::path& input, const fs::path& exclude) {
  if (!gradescopeRoot(input, exclude).empty()) return Layout::Gradescope;
  std::string error;
  int canvas = 0, other = 0;
  for (const fs::directory_entry& e : sortedEntries(input, error)) {
    std::error_code ec;
    const fs::file_status st = e.symlink_status(ec);
    const std::string name = e.path().filename().string();
    if (isSystemName(name) || sameFile(e.path(), exclude)) continue;
    if (fs::is_directory(st)) return Layout::Plain;  // Canvas downloads are flat
    if (fs::is_regular_file(st) && parseCanvasName(name)) {
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
  using Find = void (*)(const fs::path&, const fs::path&, Inventory&);
  static const Find kFinders[] = {findPlain, findGradescope, findCanvas};  // in Layout's order
  kFinders[static_cast<int>(layout)](input, exclude, inv);
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
  // A lone uploaded archive is the submission (a6_grade opens no archive inside a folder).
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

}  // namespace a6::grader::batch
