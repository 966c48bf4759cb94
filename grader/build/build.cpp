// Building a submission's probe. See build.h for the contract.
//
// Build notes: compiling is as untrusted as running (`#include "/path/to/solution/spring.cpp"`
// would copy the solution into the object, an error message would print it), so the tools run
// in the sandbox with the kit's secrets hidden, except what they need.
//
// Each task file is compiled alone: one that is missing, does not compile or runs out of time
// is replaced by the starter's object, so only its task loses points. A link that fails because
// of one file (it defines main() or a framework symbol, or renamed a function the framework
// calls) replaces the objects the linker blames, one at a time; the starter alone always links.
#include "build/build.h"

#include <elf.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <set>
#include <system_error>
#include <thread>

#include "sandbox/process.h"

namespace a6::grader {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using process::secondsAfter;
using process::secondsSince;

// ---- reading what the compiler and the linker said ----

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  if (from.empty()) return s;
  for (std::size_t pos = 0; (pos = s.find(from, pos)) != std::string::npos; pos += to.size()) {
    s.replace(pos, from.size(), to);
  }
  return s;
}

std::set<std::string> readSymbols(const fs::path& file) {
  std::set<std::string> symbols;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) symbols.insert(line);
  }
  return symbols;
}

std::vector<std::string> undefinedSymbols(const std::string& linkerOutput) {
  static const std::regex re("undefined reference to [`']([^'\n]*)'");
  std::vector<std::string> out;
  for (std::sregex_iterator it(linkerOutput.begin(), linkerOutput.end(), re), end; it != end;
       ++it) {
    out.push_back((*it)[1]);
  }
  return out;
}

std::string stem(const std::string& file) { return fs::path(file).stem().string(); }

// What the compiler or (`link`) the linker sees: the system, the kit, the work folder and the
// student's files; the link inputs for the linker only (`.incbin` in a compile would copy the
// reference models into the student's object); of /dev, only what cannot block the compiler.
SandboxView viewOfTools(const Kit& kit, const fs::path& workDir,
                        const std::vector<fs::path>& sources, bool link) {
  std::vector<fs::path> keep = {absoluteClean(kit.dir), workDir};
  keep.insert(keep.end(), sources.begin(), sources.end());
  for (const auto* inputs : {&kit.probeMain, &kit.modelsMain, &kit.linkInputs}) {
    for (const std::string& input : *inputs) {
      if (link && !input.empty() && input[0] == '/') keep.push_back(absoluteClean(input));
    }
  }
  return allowOnly(keep, kit.secrets);
}

Exit runTool(const Kit& kit, const SandboxView& view, const fs::path& dir,
             std::vector<std::string> argv, const Limits& limits) {
  SandboxSpec s;
  s.argv = std::move(argv);
  s.workDir = dir;
  s.removeWorkDir = false;  // it holds the object file, the probe
  s.limits = limits;
  s.env = {"PATH=/usr/bin:/bin", "LC_ALL=C", "TMPDIR=" + dir.string()};
  s.hide = view.hide;
  s.reveal = view.reveal;
  s.uid = kit.uid;
  s.gid = kit.gid;
  return runSandboxed(s);
}

// Code in an object that would run before the probe's seccomp filter: a .preinit_array entry,
// or an ifunc resolver (run while the loader relocates). "" for none, or for what is not a
// 64-bit ELF object (the linker judges it).
std::string runsBeforeFilter(const fs::path& object) {
  std::ifstream in(object, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Elf64_Ehdr eh;
  if (bytes.size() < sizeof eh || bytes.compare(0, 4, ELFMAG) != 0 ||
      bytes[EI_CLASS] != ELFCLASS64) {
    return "";
  }
  std::memcpy(&eh, bytes.data(), sizeof eh);
  auto section = [&](std::size_t i, Elf64_Shdr& sh) {
    const std::size_t at = eh.e_shoff + i * sizeof sh;
    if (eh.e_shentsize != sizeof sh || at + sizeof sh > bytes.size()) return false;
    std::memcpy(&sh, bytes.data() + at, sizeof sh);
    return true;
  };
  Elf64_Shdr names{};
  if (!section(eh.e_shstrndx, names)) return "";
  for (std::size_t i = 0; i < eh.e_shnum; ++i) {
    Elf64_Shdr sh;
    if (!section(i, sh)) break;
    const std::size_t at = names.sh_offset + sh.sh_name;
    const std::string name = at < bytes.size() ? std::string(bytes.c_str() + at) : "";
    if (name.rfind(".preinit_array", 0) == 0) return "a .preinit_array section";
    if (sh.sh_type != SHT_SYMTAB || sh.sh_entsize != sizeof(Elf64_Sym)) continue;
    for (std::size_t k = 0; k < sh.sh_size / sizeof(Elf64_Sym); ++k) {
      Elf64_Sym sym;
      const std::size_t off = sh.sh_offset + k * sizeof sym;
      if (off + sizeof sym > bytes.size()) break;
      std::memcpy(&sym, bytes.data() + off, sizeof sym);
      if (ELF64_ST_TYPE(sym.st_info) == STT_GNU_IFUNC) return "an ifunc symbol";
    }
  }
  return "";
}
// A tool the machine, not the code, may have ended: killed by a SIGKILL neither the grader nor
// its CPU limit sent, stopped at its wall-clock limit (a busy machine), or never started.
bool endedByTheMachine(const Exit& e, const Limits& limits = defaultCompileLimits()) {
  return e.kind == Exit::Kind::TimedOut || e.kind == Exit::Kind::FailedToStart ||
         killedByTheMachine(e, limits);
}

using ToolRunner = std::function<Exit(const fs::path& dir, std::vector<std::string> argv)>;

// A link the machine ended is not blamed on an object: it is done again, once.
Exit linkRetried(const ToolRunner& run, const fs::path& dir, const std::vector<std::string>& argv) {
  Exit e = run(dir, argv);
  return endedByTheMachine(e) ? run(dir, argv) : e;
}

// As probe/probe.cmake links; stripped (no symbol table to search for what the framework holds).
std::vector<std::string> linkCommand(const Kit& kit, const std::vector<std::string>& main,
                                     const std::vector<fs::path>& objects, const std::string& out) {
  std::vector<std::string> argv = {kit.compiler, "-s", "-o", out};
  argv.insert(argv.end(), main.begin(), main.end());
  for (const fs::path& o : objects) argv.push_back(o.string());
  argv.insert(argv.end(), kit.linkInputs.begin(), kit.linkInputs.end());
  return argv;
}

// After a6_probe linked: moves it into workDir and links the reference models' probe.
void linkedProbes(const Kit& kit, Build& build, const std::vector<fs::path>& objects,
                  const fs::path& workDir, const ToolRunner& run) {
  std::error_code ec;
  const fs::path linkDir = workDir / "link";
  build.probe = workDir / "a6_probe";
  fs::rename(linkDir / "a6_probe", build.probe, ec);
  if (ec) {
    build.error = "cannot move the linked probe to " + build.probe.string() + ": " + ec.message();
    return;
  }
  const Exit m =
      linkRetried(run, linkDir, linkCommand(kit, kit.modelsMain, objects, "a6_probe_models"));
  build.modelsProbe = workDir / "a6_probe_models";
  fs::rename(linkDir / "a6_probe_models", build.modelsProbe, ec);
  if (!m.ok() || ec) {
    build.error = "the probe linked, but not with the reference models' main (the linker " +
                  m.describe() + "): the grader kit is broken, rebuild it. The linker said:\n" +
                  cap(m.output, 8u << 10);
  }
}

// The tasks a failed link is blamed on, first blamed first: the objects the linker names, in
// its order, then those whose starter defines a symbol the linker found undefined.
std::vector<std::size_t> blamedForLink(const Kit& kit, const Build& build,
                                       const std::vector<fs::path>& objects,
                                       const std::string& linkerOutput) {
  std::vector<std::pair<std::size_t, std::size_t>> blamed;  // (position in output, task)
  const auto undefined = undefinedSymbols(linkerOutput);
  for (std::size_t i = 0; i < build.tasks.size(); ++i) {
    if (build.tasks[i].status != TaskBuild::Status::Compiled) continue;
    const std::size_t pos = linkerOutput.find(objects[i].string());
    if (pos != std::string::npos) {
      blamed.emplace_back(pos, i);
      continue;
    }
    const auto defined = readSymbols(kit.starterObjects / (stem(kTaskFiles[i]) + ".syms"));
    if (std::any_of(undefined.begin(), undefined.end(),
                    [&](const std::string& symbol) { return defined.count(symbol) > 0; })) {
      blamed.emplace_back(linkerOutput.size(), i);
    }
  }
  std::sort(blamed.begin(), blamed.end());
  std::vector<std::size_t> tasks;
  for (const auto& b : blamed) tasks.push_back(b.second);
  return tasks;
}

// What the linker said, with the grader's paths cut to names a student can read.
std::string linkerSaid(const Kit& kit, const fs::path& workDir, const std::string& output) {
  std::string said = replaceAll(output, workDir.string() + "/obj/", "");
  said = replaceAll(said, absoluteClean(kit.dir).string() + "/", "kit/");
  for (const auto* inputs : {&kit.probeMain, &kit.modelsMain, &kit.linkInputs}) {
    for (const std::string& input : *inputs) {
      if (!input.empty() && input[0] == '/') {
        said = replaceAll(said, input, fs::path(input).filename().string());
      }
    }
  }
  for (const fs::path& secret : kit.secrets) {
    said = replaceAll(said, absoluteClean(secret).string() + "/", "");
  }
  return cap(said, 8u << 10);
}

// Task i is linked with the starter's object from now on, and its messages say why.
void useStarterObject(const Kit& kit, Build& build, std::vector<fs::path>& objects, std::size_t i,
                      bool wholeSubmission, const std::string& said) {
  TaskBuild& task = build.tasks[i];
  task.status = TaskBuild::Status::LinkError;
  task.messages += task.file + " compiled, but the probe " +
                   (wholeSubmission ? std::string("did not link with the submission's objects")
                                    : "did not link with its object") +
                   " (does it define main(), or a function the framework defines, or "
                   "did it rename a function the framework calls?): task " +
                   std::to_string(i + 1) +
                   " is graded with the starter's stub. The linker said:\n" + said;
  objects[i] = kit.starterObjects / (stem(task.file) + ".o");
}

// Links workDir/a6_probe from `objects` (one per task), replacing a student object that keeps
// it from linking by the starter's (a LinkError), until it links.
void linkProbe(const Kit& kit, Build& build, std::vector<fs::path>& objects,
               const fs::path& workDir, const ToolRunner& run) {
  std::error_code ec;
  const fs::path linkDir = workDir / "link";
  const auto linkStart = Clock::now();
  for (;;) {
    const Exit e = linkRetried(run, linkDir, linkCommand(kit, kit.probeMain, objects, "a6_probe"));
    if (e.ok() && fs::is_regular_file(linkDir / "a6_probe", ec)) {
      linkedProbes(kit, build, objects, workDir, run);
      break;
    }
    std::vector<std::size_t> blamed = blamedForLink(kit, build, objects, e.output);
    // As a last resort, every student object at once.
    const bool lastResort = blamed.empty();
    for (std::size_t i = 0; lastResort && i < build.tasks.size(); ++i) {
      if (build.tasks[i].status == TaskBuild::Status::Compiled) blamed.push_back(i);
    }
    if (blamed.empty()) {
      build.error = "the probe does not link even with the starter's objects (the linker " +
                    e.describe() +
                    "): the grader kit is broken, rebuild it (cmake --build BUILD --target "
                    "a6_grader_kit). The linker said:\n" +
                    cap(e.output, 16u << 10);
      break;
    }
    const std::string said = linkerSaid(kit, workDir, e.output);
    for (std::size_t k = 0; k < (lastResort ? blamed.size() : 1); ++k) {
      useStarterObject(kit, build, objects, blamed[k], lastResort, said);
    }
  }
  build.linkSeconds = secondsSince(linkStart);
}

// The outermost folder on the way to `path` (or `path`) that `uid` may not pass, with mode and
// owner: "/root/a6/build (mode 0700, owner uid 0)"; "" when the bits allow it all.
std::string whatShutsOut(const fs::path& path, uid_t uid, gid_t gid) {
  fs::path at;
  for (const fs::path& part : path) {
    at /= part;
    struct stat st;
    if (::stat(at.c_str(), &st) != 0) return "";
    const bool last = at == path;
    const unsigned want = S_ISDIR(st.st_mode) ? (last ? 5u : 1u) : 4u;
    if (!permits(st, uid, gid, want)) {
      char mode[8];
      std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
      return at.string() + " (mode " + mode + ", owner uid " + std::to_string(st.st_uid) + ")";
    }
  }
  return "";
}

// Makes workDir/obj, open to the sandbox's user. Returns an error, or "".
std::string makeWorkDir(const fs::path& workDir) {
  std::error_code ec;
  fs::create_directories(workDir / "obj", ec);
  if (ec) return "cannot create the work folder " + workDir.string() + ": " + ec.message();
  fs::permissions(workDir, kOpenFolder, ec);
  fs::permissions(workDir / "obj", kOpenFolder, ec);
  return "";
}

// One build of one submission's probe: each task file compiled alone (`jobs` at a time) within
// what is left of the build's budget, then the link.
class ProbeBuilder {
 public:
  ProbeBuilder(const Kit& kit, const Intake& intake, const fs::path& workDir,
               const Limits& compileLimits, double budgetSeconds)
      : kit_(kit),
        intake_(intake),
        workDir_(workDir),
        compileLimits_(compileLimits),
        budgetSeconds_(budgetSeconds),
        end_(secondsAfter(Clock::now(), budgetSeconds)),
        linkView_(viewOfTools(kit, workDir, sourceDirs(intake), true)),
        objects_(kTaskFiles.size()) {
    build_.tasks.resize(kTaskFiles.size());
  }

  Build run(int jobs) {
    compileAll(jobs);
    linkProbe(kit_, build_, objects_, workDir_,
              [this](const fs::path& dir, std::vector<std::string> argv) {
                return runInBudget(dir, linkView_, std::move(argv));
              });
    return std::move(build_);
  }

 private:
  static std::vector<fs::path> sourceDirs(const Intake& intake) {
    std::vector<fs::path> dirs;
    for (const auto& [name, path] : intake.files) {
      dirs.push_back(absoluteClean(path).parent_path());
    }
    return dirs;
  }

  // Runs a tool within what is left of the budget (a link gets at least kLinkAllowance).
  Exit runInBudget(const fs::path& dir, const SandboxView& view, std::vector<std::string> argv) {
    const bool link = dir.filename() == "link";
    Limits limits = compileLimits_;
    const double left = std::chrono::duration<double>(end_ - Clock::now()).count();
    limits.wallSeconds = std::max(link ? kLinkAllowance : 1.0, std::min(limits.wallSeconds, left));
    Exit e = runTool(kit_, view, dir, std::move(argv), limits);
    for (const std::string& n : e.notes) addNote(n);
    return e;
  }

  void addNote(const std::string& note) {
    std::lock_guard<std::mutex> lock(notesMutex_);
    if (std::find(build_.notes.begin(), build_.notes.end(), note) == build_.notes.end()) {
      build_.notes.push_back(note);
    }
  }

  void compileAll(int jobs) {
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
      for (std::size_t i; (i = next++) < kTaskFiles.size();) compile(i);
    };
    std::vector<std::thread> workers;
    try {
      for (int k = 1; k < std::max(1, jobs); ++k) workers.emplace_back(worker);
    } catch (const std::system_error&) {
      // No more threads: the ones started and this one do the rest.
    }
    worker();
    for (std::thread& t : workers) t.join();
  }

  std::string stub(std::size_t i) const {
    return "task " + std::to_string(i + 1) + " is graded with the starter's stub.\n";
  }

  // Compiles task i's file alone; its task keeps the starter's object unless it compiles.
  void compile(std::size_t i) {
    TaskBuild& task = build_.tasks[i];
    task.file = kTaskFiles[i];
    objects_[i] = kit_.starterObjects / (stem(task.file) + ".o");
    std::error_code ec;
    auto found = intake_.files.find(task.file);
    if (found == intake_.files.end() || !fs::is_regular_file(found->second, ec)) {
      task.status = TaskBuild::Status::Missing;
      task.messages = task.file + " is not in the submission: " + stub(i);
      return;
    }
    if (Clock::now() >= end_) {
      task.status = TaskBuild::Status::TimedOut;
      task.messages =
          "The build's time budget (" + std::to_string(static_cast<int>(budgetSeconds_)) +
          " s for all files) was used up before " + task.file + " was compiled: " + stub(i);
      return;
    }
    const fs::path source = absoluteClean(found->second);
    if (useKnownObject(i, source)) return;
    Exit e = runCompiler(i, source);
    // A compile the machine ended is done again, once, while the budget lasts: only a failure
    // that repeats is charged.
    if (endedByTheMachine(e, compileLimits_) && Clock::now() < end_) {
      addNote("the compile of " + task.file + " " + e.describe() + ": it was done again");
      e = runCompiler(i, source);
    }
  }

  // Task i from Kit::knownObjects when its file is, byte for byte, a text the grader's build
  // compiled: nothing a submission wrote is ever shared with another.
  bool useKnownObject(std::size_t i, const fs::path& source) {
    TaskBuild& task = build_.tasks[i];
    if (kit_.knownObjects.empty()) return false;
    const fs::path known = kit_.knownObjects / (stem(task.file) + ".o");
    std::string why;  // a text that cannot be read is no known one
    const auto ours = readNoFollow(kit_.knownObjects / task.file, SIZE_MAX - 1, why);
    if (!ours || readNoFollow(source, SIZE_MAX - 1, why) != ours) return false;
    const auto t0 = Clock::now();
    const fs::path dir = workDir_ / "obj" / stem(task.file);
    const fs::path object = dir / (stem(task.file) + ".o");
    std::error_code ec;
    fs::remove_all(dir, ec);
    fs::create_directories(dir, ec);
    fs::copy_file(known, object, fs::copy_options::overwrite_existing, ec);
    if (ec) return false;
    fs::permissions(dir, kOpenFolder, ec);
    fs::permissions(object, kReadableFile, ec);
    task.status = TaskBuild::Status::Compiled;
    task.object = objects_[i] = object;
    task.known = true;
    task.seconds = secondsSince(t0);
    return true;
  }

  // Compiles task i's file and judges the outcome; __FILE__ is the file's name alone.
  Exit runCompiler(std::size_t i, const fs::path& source) {
    TaskBuild& task = build_.tasks[i];
    std::vector<std::string> argv = {kit_.compiler};
    argv.insert(argv.end(), kit_.compileFlags.begin(), kit_.compileFlags.end());
    argv.insert(argv.end(), {"-ffile-prefix-map=" + source.parent_path().string() + "/=", "-c",
                             source.string(), "-o", stem(task.file) + ".o"});
    const fs::path dir = workDir_ / "obj" / stem(task.file);
    const auto t0 = Clock::now();
    const Exit e = runInBudget(dir, viewOfTools(kit_, dir, {source}, false), argv);
    task.seconds = secondsSince(t0);
    judge(i, source, e);
    return e;
  }

  void judge(std::size_t i, const fs::path& source, const Exit& e) {
    TaskBuild& task = build_.tasks[i];
    // The file named as the student knows it, the headers as a6/... .
    std::string said = replaceAll(e.output, source.parent_path().string() + "/", "");
    said = replaceAll(said, absoluteClean(kit_.dir).string() + "/include/", "");
    task.messages = cap(said, 32u << 10);
    if (e.outputTruncated) task.messages += "[... the compiler's output was cut]\n";
    const fs::path object = workDir_ / "obj" / stem(task.file) / (stem(task.file) + ".o");
    std::error_code ec;
    if (e.kind == Exit::Kind::TimedOut) {
      task.status = TaskBuild::Status::TimedOut;
      task.messages += "The compiler did not finish " + task.file + " within " +
                       std::to_string(static_cast<int>(e.wallSeconds + 0.5)) + " s (" +
                       std::to_string(static_cast<int>(compileLimits_.wallSeconds)) +
                       " s a file, " + std::to_string(static_cast<int>(budgetSeconds_)) +
                       " s for the whole build): " + stub(i);
    } else if (!e.ok() || !fs::is_regular_file(object, ec)) {
      task.status = TaskBuild::Status::CompileError;
      if (said.find("virtual memory exhausted") != std::string::npos ||
          said.find("out of memory") != std::string::npos) {
        task.messages += "The compiler ran out of its " +
                         std::to_string(compileLimits_.memoryBytes >> 20) + " MiB of memory.\n";
      }
      task.messages +=
          task.file + " did not compile (the compiler " + e.describe() + "): " + stub(i);
    } else if (const std::string early = runsBeforeFilter(object); !early.empty()) {
      task.status = TaskBuild::Status::LinkError;
      task.messages += task.file + " compiled, but its object holds " + early +
                       ": code that would run before the grader's protections are on. Task " +
                       std::to_string(i + 1) + " is graded with the starter's stub.\n";
    } else {
      task.status = TaskBuild::Status::Compiled;
      task.object = object;
      objects_[i] = object;
    }
  }

  const Kit& kit_;
  const Intake& intake_;
  const fs::path workDir_;
  const Limits compileLimits_;
  const double budgetSeconds_;
  const Clock::time_point end_;
  const SandboxView linkView_;
  Build build_;
  std::vector<fs::path> objects_;  // the object linked for each task
  std::mutex notesMutex_;
};

}  // namespace

std::string kitUnreadableInSandbox(const Kit& kit, const fs::path& workDir) {
  if (::geteuid() != 0 || kit.uid == 0) return "";  // the tools run as this user
  std::vector<std::string> paths;
  std::error_code ec;
  const fs::path dir = absoluteClean(kit.dir);
  paths.push_back(dir.string());
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    paths.push_back(it->path().string());
  }
  for (const auto* inputs : {&kit.probeMain, &kit.modelsMain, &kit.linkInputs}) {
    for (const std::string& input : *inputs) paths.push_back(input);
  }
  // One shell in the tools' own sandbox and view tries them all: the first it cannot read.
  std::vector<std::string> argv = {
      "/bin/sh", "-c",
      "for p; do if [ -d \"$p\" ]; then [ -r \"$p\" ] && [ -x \"$p\" ]; else [ -r \"$p\" ]; fi "
      "|| { printf '%s' \"$p\"; exit 3; }; done",
      "sh"};
  argv.insert(argv.end(), paths.begin(), paths.end());
  const fs::path probeDir = absoluteClean(workDir) / "kit-check";
  const Exit e = runTool(kit, viewOfTools(kit, probeDir, {}, true), probeDir, argv, Limits{});
  std::error_code rec;
  fs::remove_all(probeDir, rec);
  if (e.ok()) return "";
  if (e.kind != Exit::Kind::Exited || e.code != 3) return "";  // the tools will say what is wrong
  const std::string culprit = whatShutsOut(e.output, kit.uid, kit.gid);
  const bool itself = culprit.rfind(e.output + " (", 0) == 0;
  return "the sandbox's user (uid " + std::to_string(kit.uid) + ") cannot read " +
         (itself ? culprit : e.output + (culprit.empty() ? "" : ", shut out by " + culprit)) +
         ": make the grader's build readable by every user (chmod -R a+rX " +
         (isWithin(fs::path(e.output), dir) ? dir : fs::path(e.output).parent_path()).string() +
         ", or build it with umask 022), then grade again";
}

Build buildProbe(const Kit& kit, const Intake& intake, const fs::path& workDirIn,
                 const Limits& compileLimits, int jobs, double budgetSeconds) {
  const auto start = Clock::now();
  Build build;
  try {
    const fs::path workDir = absoluteClean(workDirIn);
    if (!kit.ok()) {
      build.error = "no grader kit: " + kit.error;
    } else if (std::string e = makeWorkDir(workDir); !e.empty()) {
      build.error = e;
    } else {
      build = ProbeBuilder(kit, intake, workDir, compileLimits, budgetSeconds).run(jobs);
    }
  } catch (const std::exception& e) {
    Build failed;
    failed.error = std::string("building the probe failed: ") + e.what();
    return failed;
  }
  build.seconds = secondsSince(start);
  return build;
}

Build relinkProbe(const Kit& kit, const Build& compiled, const std::set<std::string>& starterFor,
                  const fs::path& workDirIn) {
  Build build;
  const auto start = Clock::now();
  try {
    std::error_code ec;
    const fs::path workDir = absoluteClean(workDirIn);
    fs::create_directories(workDir / "link", ec);
    fs::permissions(workDir, kOpenFolder, ec);
    build.tasks = compiled.tasks;
    std::vector<fs::path> objects;
    std::vector<fs::path> keep;
    for (TaskBuild& task : build.tasks) {
      const bool own = task.status == TaskBuild::Status::Compiled && !starterFor.count(task.file);
      if (!own && task.status == TaskBuild::Status::Compiled)
        task.status = TaskBuild::Status::LinkError;
      objects.push_back(own ? task.object : kit.starterObjects / (stem(task.file) + ".o"));
      if (own) keep.push_back(absoluteClean(task.object).parent_path());
    }
    const SandboxView view = viewOfTools(kit, workDir, keep, true);
    linkProbe(kit, build, objects, workDir,
              [&](const fs::path& dir, std::vector<std::string> argv) {
                return runTool(kit, view, dir, std::move(argv), defaultCompileLimits());
              });
  } catch (const std::exception& e) {
    build.error = std::string("linking the probe failed: ") + e.what();
  }
  build.seconds = secondsSince(start);
  return build;
}

}  // namespace a6::grader
