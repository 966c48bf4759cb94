// What the sandboxed child will do, prepared in the parent before fork (plan.h), and the
// sentence for each step the child reports as failed.
#include "sandbox/plan.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <map>

#include "sandbox/process.h"

namespace a6::grader::sandboxing {

namespace fs = std::filesystem;

namespace {

const char* limitName(int resource) {
  static const std::map<int, const char*> kNames = {
      {RLIMIT_CPU, "RLIMIT_CPU"},     {RLIMIT_AS, "RLIMIT_AS"},
      {RLIMIT_FSIZE, "RLIMIT_FSIZE"}, {RLIMIT_NOFILE, "RLIMIT_NOFILE"},
      {RLIMIT_NPROC, "RLIMIT_NPROC"}, {RLIMIT_CORE, "RLIMIT_CORE"}};
  const auto it = kNames.find(resource);
  return it == kNames.end() ? "an rlimit" : it->second;
}

// Tasks (threads) of a user, from /proc: RLIMIT_NPROC counts them all.
long tasksOf(uid_t uid) {
  long total = 0;
  for (const process::Info& p : process::all()) {
    if (p.realUid == uid) total += std::max(1, p.threads);
  }
  return total;
}

std::size_t depthOf(const fs::path& path) {
  return static_cast<std::size_t>(std::distance(path.begin(), path.end()));
}

// Creates the work dir fresh and empty, writable by the user the child runs as.
std::string prepareWorkDir(const fs::path& dir, const Plan& plan) {
  if (dir.empty()) return "no work dir given";
  const fs::path abs = fs::absolute(dir).lexically_normal();
  if (abs == abs.root_path() || depthOf(abs) < 3) {
    return "refusing to use " + abs.string() + " as a work dir (too close to /)";
  }
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(abs, ec);
  if (fs::exists(st)) {
    fs::remove_all(abs, ec);  // a link itself, never its target
    if (ec) return "cannot empty the work dir " + abs.string() + ": " + ec.message();
  }
  fs::create_directories(abs, ec);
  if (ec) return "cannot create the work dir " + abs.string() + ": " + ec.message();
  ::chmod(abs.c_str(), 0700);
  if (plan.dropPrivileges && ::chown(abs.c_str(), plan.uid, plan.gid) != 0) {
    return "cannot hand the work dir " + abs.string() + " to uid " + std::to_string(plan.uid) +
           ": " + errnoText(errno);
  }
  return "";
}

// The paths a child must see whatever is hidden: SandboxSpec::reveal, its work dir, argv[0].
std::vector<fs::path> revealsOf(const SandboxSpec& spec, const Plan& plan) {
  std::vector<fs::path> reveals;
  for (const fs::path& r : spec.reveal) reveals.push_back(absoluteClean(r));
  reveals.push_back(absoluteClean(plan.workDir));
  reveals.push_back(absoluteClean(spec.argv[0]));
  return reveals;
}

// A folder the child's user cannot search (a checkout in /root, 0700) would shut it out of a
// reveal inside: the outermost such folder is covered, and the reveal rebuilds the way in.
std::vector<fs::path> unsearchableAncestors(const std::vector<fs::path>& reveals,
                                            const Plan& plan) {
  std::vector<fs::path> covers;
  for (const fs::path& path : reveals) {
    fs::path ancestor;
    for (auto part = path.begin(); part != path.end(); ++part) {
      ancestor /= *part;
      if (ancestor == path || ancestor == ancestor.root_path()) continue;
      struct stat st;
      if (stat(ancestor.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) break;
      if (!permits(st, plan.uid, plan.gid, 1)) {  // the child drops its groups
        if (std::find(covers.begin(), covers.end(), ancestor) == covers.end()) {
          covers.push_back(ancestor);
        }
        break;
      }
    }
  }
  return covers;
}

// The paths to hide: the spec's, and as a dropped user the unsearchable folders above a reveal.
std::vector<fs::path> hidesOf(const SandboxSpec& spec, const std::vector<fs::path>& reveals,
                              const Plan& plan) {
  std::vector<fs::path> hides;
  for (const fs::path& h : spec.hide) hides.push_back(absoluteClean(h));
  if (plan.dropPrivileges) {
    for (const fs::path& c : unsearchableAncestors(reveals, plan)) hides.push_back(c);
  }
  return hides;
}

// One hide operation per existing path (as root); returns the paths hidden.
std::vector<fs::path> planHides(const std::vector<fs::path>& hides, Plan& plan) {
  std::vector<fs::path> hidden;
  bool unhidden = false;
  for (const fs::path& path : hides) {
    struct stat st;
    if (lstat(path.c_str(), &st) != 0) continue;  // nothing to hide
    if (path == path.root_path()) {
      plan.notes.push_back("refusing to hide / (everything would be hidden)");
      continue;
    }
    if (!plan.root) {
      unhidden = true;
      continue;
    }
    MountOp op;
    op.kind = S_ISDIR(st.st_mode) ? MountOp::HideDir : MountOp::HideFile;
    op.path = path.string();
    op.depth = depthOf(path);
    plan.ops.push_back(op);
    hidden.push_back(path);
  }
  if (unhidden) plan.notes.push_back(kNotRootNote);
  return hidden;
}

// One reveal operation per revealed path that lies under a hidden one.
void planReveals(const std::vector<fs::path>& reveals, const std::vector<fs::path>& hidden,
                 Plan& plan) {
  for (const fs::path& path : reveals) {
    if (std::none_of(hidden.begin(), hidden.end(),
                     [&](const fs::path& h) { return isWithin(path, h); })) {
      continue;
    }
    MountOp op;
    op.kind = MountOp::Reveal;
    op.path = path.string();
    op.depth = depthOf(path);
    struct stat st;
    if (stat(path.c_str(), &st) != 0) {
      plan.notes.push_back("cannot keep " + op.path + " visible: " + errnoText(errno));
      continue;
    }
    op.isDir = S_ISDIR(st.st_mode);
    for (fs::path a = path.parent_path(); a != a.root_path(); a = a.parent_path()) {
      op.chain.insert(op.chain.begin(), a.string());
    }
    plan.ops.push_back(op);
  }
}

// SandboxSpec::hide and reveal as mount operations, outer paths first; not as root, a note.
void planMounts(const SandboxSpec& spec, Plan& plan) {
  const std::vector<fs::path> reveals = revealsOf(spec, plan);
  const std::vector<fs::path> hidden = planHides(hidesOf(spec, reveals, plan), plan);
  if (plan.ops.empty()) return;
  planReveals(reveals, hidden, plan);
  // Outer paths first; at equal depth, hide before revealing.
  std::stable_sort(plan.ops.begin(), plan.ops.end(), [](const MountOp& a, const MountOp& b) {
    if (a.depth != b.depth) return a.depth < b.depth;
    return (a.kind == MountOp::Reveal ? 1 : 0) < (b.kind == MountOp::Reveal ? 1 : 0);
  });
}

// Who the child runs as, and its argv and envp arrays (pointing into plan's own strings).
void planProgram(const SandboxSpec& spec, Plan& plan) {
  plan.root = geteuid() == 0;
  plan.dropPrivileges = plan.root && spec.uid != 0;
  plan.uid = spec.uid;
  plan.gid = spec.gid;
  plan.parent = getpid();  // forkChild sets the keeper instead when it makes a pid namespace
  plan.args = spec.argv;
  plan.envs = spec.env;
  for (std::string& a : plan.args) plan.argv.push_back(a.data());
  plan.argv.push_back(nullptr);
  for (std::string& e : plan.envs) plan.envp.push_back(e.data());
  plan.envp.push_back(nullptr);
}

// The work dir, and as root the options of the tmpfs laid over it.
std::string planWorkDir(const SandboxSpec& spec, Plan& plan) {
  if (std::string e = prepareWorkDir(spec.workDir, plan); !e.empty()) return e;
  plan.workDir = fs::absolute(spec.workDir).lexically_normal().string();
  if (plan.root && spec.workDirTmpfsBytes > 0) {
    plan.workTmpfs = "size=" + std::to_string(spec.workDirTmpfsBytes) +
                     ",mode=0700,uid=" + std::to_string(plan.dropPrivileges ? plan.uid : 0) +
                     ",gid=" + std::to_string(plan.dropPrivileges ? plan.gid : 0);
  }
  return "";
}

// The rlimits, in the order the child sets them.
void planLimits(const Limits& l, Plan& plan) {
  const auto cpu = static_cast<rlim_t>(std::max(1.0, std::ceil(l.cpuSeconds)));
  plan.limits.push_back({RLIMIT_CPU, cpu, cpu + 1});  // SIGXCPU first, SIGKILL a second later
  plan.limits.push_back({RLIMIT_AS, l.memoryBytes, l.memoryBytes});
  plan.limits.push_back({RLIMIT_FSIZE, l.fileSizeBytes, l.fileSizeBytes});
  const auto files = static_cast<rlim_t>(std::max(8, l.openFiles));
  plan.limits.push_back({RLIMIT_NOFILE, files, files});
  plan.limits.push_back({RLIMIT_CORE, 0, 0});
  const long tasks = tasksOf(plan.dropPrivileges ? plan.uid : getuid());
  const auto nproc = static_cast<rlim_t>(tasks + 1 + std::max(0, l.processes));
  plan.limits.push_back({RLIMIT_NPROC, nproc, nproc});
}

// The fds the child receives, and the free range above them it moves them through. Returns an
// error, or "".
std::string planFds(const SandboxSpec& spec, Plan& plan) {
  int highest = 2;
  for (const auto& [from, to] : spec.mapFds) {
    if (to < 3) return "mapFds: child fd " + std::to_string(to) + " is one of 0, 1, 2";
    plan.fds.push_back({from, to});
    highest = std::max(highest, to);
  }
  if (plan.fds.size() > 64) return "too many fds to pass (64 at most)";
  plan.highBase = highest + 1;
  rlimit nofile{};
  getrlimit(RLIMIT_NOFILE, &nofile);
  plan.maxFd = static_cast<int>(std::min<rlim_t>(nofile.rlim_cur, 65536));
  if (plan.highBase + 70 > plan.maxFd) return "fd numbers too high to pass";
  return "";
}

// What a failed step says: $ stands for its subject (subjectOf), % for the errno's text.
const std::map<int, const char*> kSentences = {
    {kSetsid, "setsid: %"},
    {kUnshareMounts,
     "could not hide the grader's files (unshare(CLONE_NEWNS): %): only file permissions "
     "protect them"},
    {kMountPrivate,
     "could not hide the grader's files (making / private: %): only file permissions protect "
     "them"},
    {kHide, "could not hide $ (mount: %)"},
    {kReveal, "could not keep $ visible under a hidden path: %"},
    {kUnshareNet,
     "no network namespace (unshare(CLONE_NEWNET): %): sockets are refused by the seccomp filter "
     "only"},
    {kDevNull, "opening /dev/null: %"},
    {kFds, "passing file descriptors: %"},
    {kRlimit, "setting $: %"},
    {kChdir, "entering the work dir $: %"},
    {kSetgroups, "dropping supplementary groups: %"},
    {kSetgid, "switching to gid $: %"},
    {kSetuid, "switching to uid $: %"},
    {kDeathSignal, "setting the parent-death signal: %"},
    {kNoNewPrivs, "setting no_new_privs: %"},
    {kSeccomp, "could not install the seccomp filter (%): sockets are not refused"},
    {kExec, "exec $: %"},
    {kWorkTmpfs, "mounting a tmpfs on the work dir $: %"},
    {kProc,
     "could not mount the pid namespace's own /proc (%): the code sees the machine's processes "
     "in /proc (it still cannot signal them)"},
    {kFork, "starting the program in its pid namespace (fork): %"},
};

// What the step failed on: the path, the limit, the work dir, the id, the program; or "".
std::string subjectOf(const Record& r, const Plan& plan, const SandboxSpec& spec) {
  const auto at = static_cast<std::size_t>(r.index);
  switch (r.stage) {
    case kHide:
    case kReveal:
      return r.index >= 0 && at < plan.ops.size() ? plan.ops[at].path : "";
    case kRlimit:
      return r.index >= 0 && at < plan.limits.size() ? limitName(plan.limits[at].resource)
                                                     : "an rlimit";
    case kChdir:
    case kWorkTmpfs:
      return plan.workDir;
    case kSetgid:
      return std::to_string(plan.gid);
    case kSetuid:
      return std::to_string(plan.uid);
    case kExec:
      return spec.argv[0];
    default:
      return "";
  }
}

}  // namespace

void deleteWorkDir(const std::string& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  fs::remove_all(dir, ec);
}

std::string makePlan(const SandboxSpec& spec, Plan& plan) {
  if (spec.argv.empty() || spec.argv[0].empty() || spec.argv[0][0] != '/') {
    return "argv[0] must be an absolute path" +
           (spec.argv.empty() ? std::string() : " (got '" + spec.argv[0] + "')");
  }
  planProgram(spec, plan);
  if (std::string e = planWorkDir(spec, plan); !e.empty()) return e;
  planMounts(spec, plan);
  planLimits(spec.limits, plan);
  if (std::string e = planFds(spec, plan); !e.empty()) return e;
  std::string filterError;
  plan.filter = filterFor(spec.limits.processes <= 0, filterError);
  if (!filterError.empty()) plan.notes.push_back(filterError + "; sockets are not refused");
  return "";
}

std::string describeRecord(const Record& r, const Plan& plan, const SandboxSpec& spec) {
  const std::string err = errnoText(r.err);
  const auto sentence = kSentences.find(r.stage);
  if (sentence == kSentences.end()) {
    return "unknown setup stage " + std::to_string(r.stage) + ": " + err;
  }
  std::string text;
  for (const char* c = sentence->second; *c != '\0'; ++c) {
    text += *c == '$' ? subjectOf(r, plan, spec) : *c == '%' ? err : std::string(1, *c);
  }
  if (r.stage == kExec && r.err == EACCES && plan.dropPrivileges) {
    text += " (it runs as uid " + std::to_string(plan.uid) +
            ": the program and every folder above it must be readable and searchable by "
            "other users)";
  }
  return text;
}

}  // namespace a6::grader::sandboxing
