#include "metricmap/io/atomic_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/syscall.h>
#include <sys/types.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "metricmap/io/checked_file.h"
#include "metricmap/io/output_set.h"

namespace metricmap {
namespace {

namespace fs = std::filesystem;

// ---- the registry of live temporaries ---------------------------------------------------------
// A fixed table, so that the signal handler reads it without allocating or locking: a slot is
// claimed (kFree -> kFilling), its path written, then published (kLive); the handler only reads
// kLive slots.

constexpr int kFree = 0, kFilling = 1, kLive = 2;
constexpr std::size_t kSlots = 256;
constexpr std::size_t kPathBytes = 4096;

struct Slot {
  std::atomic<int> state{kFree};
  bool directory = false;
  char path[kPathBytes] = {};
};

Slot g_slots[kSlots];

/// Async-signal-safe: empties a directory (one level, files and empty subdirectories), then
/// removes it. Entries are listed with getdents64 into a stack buffer; the listing is restarted
/// until a pass removes nothing.
void removeDirectorySafely(const char* path) {
  const int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    struct Dirent64 {
      std::uint64_t d_ino;
      std::int64_t d_off;
      unsigned short d_reclen;
      unsigned char d_type;
      char d_name[1];
    };
    alignas(8) char buf[4096];
    for (int pass = 0; pass < 64; ++pass) {
      bool removed = false;
      ::lseek(fd, 0, SEEK_SET);
      for (;;) {
        const long n = ::syscall(SYS_getdents64, fd, buf, sizeof buf);
        if (n <= 0) break;
        for (long off = 0; off < n;) {
          const auto* d = reinterpret_cast<const Dirent64*>(buf + off);
          off += d->d_reclen;
          const char* name = d->d_name;
          if (name[0] == '.' && (name[1] == '\0' || (name[1] == '.' && name[2] == '\0'))) continue;
          if (::unlinkat(fd, name, 0) == 0 || ::unlinkat(fd, name, AT_REMOVEDIR) == 0)
            removed = true;
        }
      }
      if (!removed) break;
    }
    ::close(fd);
  }
  ::rmdir(path);
}

/// Async-signal-safe: removes every live temporary.
void removeLiveTemporaries() {
  for (Slot& s : g_slots) {
    if (s.state.load(std::memory_order_acquire) != kLive) continue;
    if (s.directory) {
      removeDirectorySafely(s.path);
    } else {
      ::unlink(s.path);
    }
  }
}

void onFatalSignal(int sig) {
  const int saved_errno = errno;
  removeLiveTemporaries();
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  errno = saved_errno;
  // The signal is blocked while its handler runs: it is delivered, with the default action
  // (the process ends as the sender meant), as soon as the handler returns.
  ::raise(sig);
}

void onExit() { removeLiveTemporaries(); }

void installHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (const int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGXCPU, SIGXFSZ, SIGABRT}) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0) continue;
      // an ignored signal stays ignored (nohup, a background job), another handler stays
      if ((old.sa_flags & SA_SIGINFO) != 0 || old.sa_handler != SIG_DFL) continue;
      struct sigaction act {};
      act.sa_handler = onFatalSignal;
      sigemptyset(&act.sa_mask);
      // every other terminating signal waits while the table is being walked
      for (const int other : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE})
        sigaddset(&act.sa_mask, other);
      act.sa_flags = SA_RESTART;
      ::sigaction(sig, &act, nullptr);
    }
    std::atexit(onExit);
  });
}

std::string absolutePath(const std::string& path) {
  if (!path.empty() && path[0] == '/') return path;
  std::error_code ec;
  const fs::path abs = fs::absolute(path, ec);
  return ec ? path : abs.string();
}

// ---- stale temporaries of dead runs -------------------------------------------------------------

bool processGone(long pid) {
  if (pid <= 0 || pid == static_cast<long>(::getpid())) return false;
  return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

/// Reads decimal digits at `pos`; false when there are none (or too many).
bool readNumber(const std::string& s, std::size_t& pos, long& value) {
  const std::size_t start = pos;
  value = 0;
  while (pos < s.size() && s[pos] >= '0' && s[pos] <= '9' && pos - start < 12) {
    value = value * 10 + (s[pos] - '0');
    ++pos;
  }
  return pos > start && (pos == s.size() || s[pos] < '0' || s[pos] > '9');
}

/// A temporary name: "<stem>.tmp-PID-N<rest>" (a file) or "<stem>.tmp-PID" (a directory);
/// gives stem, PID and rest.
bool parseTemporaryName(const std::string& name, std::string& stem, long& pid, std::string& rest,
                        bool& file_form) {
  const std::size_t at = name.find(".tmp-");
  if (at == std::string::npos) return false;
  std::size_t pos = at + 5;
  if (!readNumber(name, pos, pid)) return false;
  stem = name.substr(0, at);
  if (pos == name.size()) {
    file_form = false;
    rest.clear();
    return true;
  }
  if (name[pos] != '-') return false;
  ++pos;
  long n = 0;
  if (!readNumber(name, pos, n)) return false;
  file_form = true;
  rest = name.substr(pos);
  return true;
}

struct StaleEntry {
  std::string name, stem, rest;
  bool file_form = false;
};

std::mutex g_stale_mutex;
std::map<std::string, std::vector<StaleEntry>> g_stale_by_dir;  // directory -> dead temporaries

/// The directory's temporaries of dead processes, listed once per process.
std::vector<StaleEntry>& staleIn(const std::string& dir) {
  auto it = g_stale_by_dir.find(dir);
  if (it != g_stale_by_dir.end()) return it->second;
  std::vector<StaleEntry>& list = g_stale_by_dir[dir];
  std::map<long, bool> gone;
  std::error_code ec;
  for (fs::directory_iterator d(dir.empty() ? fs::path(".") : fs::path(dir), ec), end;
       !ec && d != end; d.increment(ec)) {
    StaleEntry e;
    e.name = d->path().filename().string();
    long pid = 0;
    if (!parseTemporaryName(e.name, e.stem, pid, e.rest, e.file_form)) continue;
    auto g = gone.find(pid);
    if (g == gone.end()) g = gone.emplace(pid, processGone(pid)).first;
    if (g->second) list.push_back(std::move(e));
  }
  return list;
}

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// stem and extension as temporaryPathFor splits a file name.
void splitName(const std::string& name, std::string& stem, std::string& ext) {
  const std::size_t dot = name.find_last_of('.');
  if (dot == std::string::npos || dot == 0) {
    stem = name;
    ext.clear();
  } else {
    stem = name.substr(0, dot);
    ext = name.substr(dot);
  }
}

}  // namespace

void registerTemporary(const std::string& path, bool directory) {
  const std::string abs = absolutePath(path);
  if (abs.size() >= kPathBytes) return;  // no such file can be created either
  installHandlers();
  for (Slot& s : g_slots) {
    int expected = kFree;
    if (!s.state.compare_exchange_strong(expected, kFilling, std::memory_order_acq_rel)) continue;
    s.directory = directory;
    std::memcpy(s.path, abs.c_str(), abs.size() + 1);
    s.state.store(kLive, std::memory_order_release);
    return;
  }
  throw std::runtime_error(outputDisplayName(path) +
                           ": cannot write (more than 256 temporary files at once)");
}

void forgetTemporary(const std::string& path) {
  const std::string abs = absolutePath(path);
  for (Slot& s : g_slots) {
    if (s.state.load(std::memory_order_acquire) != kLive) continue;
    if (std::strcmp(s.path, abs.c_str()) != 0) continue;
    int expected = kLive;
    s.state.compare_exchange_strong(expected, kFree, std::memory_order_acq_rel);
    return;
  }
}

std::size_t removeStaleTemporaries(const std::string& path) {
  std::string trimmed = path;
  while (trimmed.size() > 1 && trimmed.back() == '/') trimmed.pop_back();
  const std::size_t slash = trimmed.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "" : trimmed.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? trimmed : trimmed.substr(slash + 1);
  if (base.empty()) return 0;
  std::string stem, ext;
  splitName(base, stem, ext);
  std::size_t removed = 0;
  std::error_code ec;
  std::lock_guard<std::mutex> lock(g_stale_mutex);
  std::vector<StaleEntry>& stale = staleIn(dir);
  for (auto it = stale.begin(); it != stale.end();) {
    // a file: stem.tmp-PID-N.ext, or a temporary's temporary (stem.tmp-PID-N.tmp-...ext); a
    // directory output: base.tmp-PID
    const bool mine =
        it->file_form
            ? it->stem == stem &&
                  (it->rest == ext || (it->rest.rfind(".tmp-", 0) == 0 && endsWith(it->rest, ext)))
            : it->stem == base;
    if (!mine) {
      ++it;
      continue;
    }
    removed += fs::remove_all(fs::path(dir.empty() ? "." : dir) / it->name, ec) > 0 ? 1 : 0;
    it = stale.erase(it);
  }
  // a directory output that exists: its staged files went to DIR/.tmp-PID
  std::error_code dir_ec;
  if (fs::is_directory(trimmed, dir_ec)) {
    const std::string inside = trimmed + "/";
    for (const StaleEntry& e : staleIn(inside)) {
      if (!e.file_form && e.stem.empty())
        removed += fs::remove_all(inside + e.name, ec) > 0 ? 1 : 0;
    }
    g_stale_by_dir.erase(inside);
  }
  return removed;
}

std::string temporaryPathFor(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  removeStaleTemporaries(path);
  const std::string tag = ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  std::string tmp;
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) ||
      dot == (slash == std::string::npos ? 0 : slash + 1)) {
    tmp = path + tag;
  } else {
    tmp = path.substr(0, dot) + tag + path.substr(dot);
  }
  registerTemporary(tmp);
  return tmp;
}

void discardTemporary(const std::string& temporary) {
  std::remove(temporary.c_str());
  forgetTemporary(temporary);
}

void commitTemporary(const std::string& temporary, const std::string& path) {
  try {
    checkOutputPath(path);
  } catch (...) {
    discardTemporary(temporary);
    throw;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int err = errno;
    discardTemporary(temporary);
    throw std::runtime_error(outputDisplayName(path) + ": cannot write (" + std::strerror(err) +
                             ")");
  }
  forgetTemporary(temporary);
}

}  // namespace metricmap
