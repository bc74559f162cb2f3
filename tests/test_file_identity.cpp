// File identity (one file however it is spelled) and the temporaries of interrupted runs.
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "metricmap/io/atomic_file.h"
#include "metricmap/io/cloud_writer.h"
#include "metricmap/io/file_identity.h"
#include "metricmap/io/output_set.h"

#include "temp_dir.h"

namespace metricmap {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& p) { std::ofstream(p) << "x"; }

/// A PID that is not running: a child that has exited and been reaped.
pid_t deadPid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return pid;
}

}  // namespace

TEST(FileIdentity, OneFileHoweverSpelled) {
  TempDir d("identity");
  fs::create_directory(d / "sub");
  touch(d / "a.pcd");
  fs::create_symlink("a.pcd", d / "link.pcd");
  fs::create_hard_link(d / "a.pcd", d / "hard.pcd");
  fs::create_directory_symlink(d.path, d / "dirlink");
  const FileIdentity a = fileIdentity(d / "a.pcd");
  EXPECT_TRUE(a.exists);
  for (const fs::path& p : std::vector<fs::path>{d / "./a.pcd", d / "sub/../a.pcd", d / "link.pcd",
                                                 d / "hard.pcd", d / "dirlink/a.pcd"}) {
    EXPECT_TRUE(sameFile(a, fileIdentity(p))) << p;
  }
  // new files: normalised absolute paths, symlinked directories resolved
  const FileIdentity n = fileIdentity(d / "new.pcd");
  EXPECT_FALSE(n.exists);
  for (const fs::path& p :
       std::vector<fs::path>{d / "./new.pcd", d / "sub/../new.pcd", d / "dirlink/new.pcd"}) {
    EXPECT_TRUE(sameFile(n, fileIdentity(p))) << p;
  }
  EXPECT_FALSE(sameFile(n, fileIdentity(d / "sub/new.pcd")));
  EXPECT_FALSE(sameFile(a, n));
}

TEST(FileIdentity, RelativeAndAbsoluteSpellings) {
  TempDir d("identity_rel");
  const fs::path cwd = fs::current_path();
  fs::current_path(d.path);
  const bool same_new = sameFile(fileIdentity("x.pcd"), fileIdentity(d / "x.pcd"));
  touch(d / "y.pcd");
  const bool same_old = sameFile(fileIdentity("./y.pcd"), fileIdentity(d / "y.pcd"));
  fs::current_path(cwd);
  EXPECT_TRUE(same_new);
  EXPECT_TRUE(same_old);
}

TEST(FileIdentity, FindsOutputsNamingInputsOrEachOther) {
  TempDir d("clash");
  touch(d / "in.pcd");
  const std::vector<RolePath> inputs = {{"input", d / "in.pcd"}, {"input", d / "other.pcd"}};
  EXPECT_FALSE(findFileClash(inputs, {{"--out", d / "out.pcd"}, {"--cells", d / "c.csv"}}));
  auto clash = findFileClash(inputs, {{"--out", d / "out.pcd"}, {"--cells", d / "./in.pcd"}});
  ASSERT_TRUE(clash);
  EXPECT_TRUE(clash->output_is_input);
  EXPECT_EQ(clash->first.first, "input");
  EXPECT_EQ(clash->second.first, "--cells");
  clash = findFileClash({}, {{"--out", d / "o.pcd"}, {"--cells", d / "x/../o.pcd"}});
  ASSERT_TRUE(clash);
  EXPECT_FALSE(clash->output_is_input);
  EXPECT_EQ(clash->first.first, "--out");
  // a missing input (read later, refused then) and an output of the same name
  EXPECT_TRUE(findFileClash(inputs, {{"--out", d / "sub/../other.pcd"}}));
  // two inputs naming one file are fine; empty paths are skipped
  EXPECT_FALSE(findFileClash({{"a", d / "in.pcd"}, {"b", d / "in.pcd"}}, {{"--out", ""}}));
}

TEST(Temporaries, StaleOnesOfDeadRunsAreRemoved) {
  TempDir d("stale");
  const std::string dead = std::to_string(deadPid());
  const std::string live = std::to_string(::getppid());
  const std::vector<std::string> stale = {"g.tmp-" + dead + "-0.pcd",
                                          "g.tmp-" + dead + "-0.tmp-" + dead + "-1.pcd"};
  const std::vector<std::string> kept = {"g.tmp-" + live + "-0.pcd",  // a live process's
                                         "h.tmp-" + dead + "-0.pcd",  // another output's
                                         "g.tmp-" + dead + "-0.csv", "g.tmp-x-0.pcd"};
  for (const auto& n : stale) touch(d / n);
  for (const auto& n : kept) touch(d / n);
  // a staged directory of a dead run (a directory is listed once per process: before the run)
  fs::create_directory(d / ("steps.tmp-" + dead));
  touch(d.path / ("steps.tmp-" + dead) / "s.svg");
  EXPECT_EQ(removeStaleTemporaries(d / "g.pcd"), stale.size());
  for (const auto& n : stale) EXPECT_FALSE(fs::exists(d / n)) << n;
  for (const auto& n : kept) EXPECT_TRUE(fs::exists(d / n)) << n;
  EXPECT_TRUE(fs::exists(d / ("steps.tmp-" + dead)));  // another output's
  EXPECT_EQ(removeStaleTemporaries(d / "steps"), 1u);
  EXPECT_FALSE(fs::exists(d / ("steps.tmp-" + dead)));
}

TEST(Temporaries, ASignalRemovesTheLiveOnes) {
  TempDir d("signal");
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    ::sigaction(sig, nullptr, &old);
    if (old.sa_handler == SIG_IGN) continue;  // ignored by whoever started the tests: stays so
    const pid_t pid = ::fork();
    if (pid == 0) {
      OutputSet set;
      writeTextAtomic(set.stage(d / "a.csv"), "one");
      const std::string dir = set.stageDirectory(d / "steps");
      writeTextAtomic(dir + "/s.svg", "two");
      const std::string open = temporaryPathFor(d / "b.csv");
      std::ofstream(open) << "partial";
      ::raise(sig);
      ::_exit(0);  // not reached: the signal ends the process
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << sig;
    EXPECT_TRUE(fs::is_empty(d.path))
        << "signal " << sig << " left " << fs::directory_iterator(d.path)->path();
  }
}

}  // namespace metricmap
