#include "metricmap/io/file_identity.h"

#include <sys/stat.h>

#include <filesystem>
#include <map>
#include <system_error>

namespace metricmap {
namespace {

namespace fs = std::filesystem;

/// Absolute, with the existing leading directories' symbolic links and ".." resolved as the
/// kernel resolves them, the rest lexically normal.
std::string normalisedPath(const std::string& path) {
  std::error_code ec;
  fs::path abs = fs::absolute(path, ec);
  if (ec) abs = fs::path(path);
  fs::path canonical = fs::weakly_canonical(abs, ec);
  if (ec) canonical = abs;
  std::string s = canonical.lexically_normal().string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();  // "dir/" and "dir" are one name
  return s;
}

}  // namespace

FileIdentity fileIdentity(const std::string& path) {
  FileIdentity id;
  struct stat st {};
  if (!path.empty() && ::stat(path.c_str(), &st) == 0) {
    id.exists = true;
    id.device = static_cast<std::uint64_t>(st.st_dev);
    id.inode = static_cast<std::uint64_t>(st.st_ino);
    return id;
  }
  id.normalised_path = normalisedPath(path);
  return id;
}

bool sameFile(const FileIdentity& a, const FileIdentity& b) {
  if (a.exists != b.exists) return false;
  if (a.exists) return a.device == b.device && a.inode == b.inode;
  return a.normalised_path == b.normalised_path;
}

std::optional<FileClash> findFileClash(const std::vector<RolePath>& inputs,
                                       const std::vector<RolePath>& outputs) {
  std::vector<std::pair<FileIdentity, const RolePath*>> seen_outputs;
  for (const RolePath& out : outputs) {
    if (out.second.empty()) continue;
    FileIdentity id = fileIdentity(out.second);
    for (const auto& [other_id, other] : seen_outputs) {
      if (sameFile(id, other_id)) return FileClash{*other, out, false};
    }
    seen_outputs.emplace_back(std::move(id), &out);
  }
  if (seen_outputs.empty()) return std::nullopt;
  // inputs once each, indexed by identity
  std::map<std::pair<std::uint64_t, std::uint64_t>, const RolePath*> existing;
  std::map<std::string, const RolePath*> missing;
  for (const RolePath& in : inputs) {
    if (in.second.empty()) continue;
    const FileIdentity id = fileIdentity(in.second);
    if (id.exists) {
      existing.emplace(std::make_pair(id.device, id.inode), &in);
    } else {
      missing.emplace(id.normalised_path, &in);
    }
  }
  for (const auto& [id, out] : seen_outputs) {
    const RolePath* in = nullptr;
    if (id.exists) {
      const auto it = existing.find({id.device, id.inode});
      if (it != existing.end()) in = it->second;
    } else {
      const auto it = missing.find(id.normalised_path);
      if (it != missing.end()) in = it->second;
    }
    if (in != nullptr) return FileClash{*in, *out, true};
  }
  return std::nullopt;
}

std::optional<std::pair<RolePath, RolePath>> findRepeatedInput(
    const std::vector<RolePath>& inputs) {
  std::map<std::pair<std::uint64_t, std::uint64_t>, const RolePath*> seen;
  for (const RolePath& in : inputs) {
    if (in.second.empty()) continue;
    const FileIdentity id = fileIdentity(in.second);
    if (!id.exists) continue;
    const auto [it, fresh] = seen.emplace(std::make_pair(id.device, id.inode), &in);
    if (!fresh) return std::make_pair(*it->second, in);
  }
  return std::nullopt;
}

}  // namespace metricmap
