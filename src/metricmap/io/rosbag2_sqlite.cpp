#include "metricmap/io/rosbag2_sqlite.h"

#include <sqlite3.h>

#include <cctype>
#include <cstdio>
#include <cstring>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/input_file.h"

namespace metricmap {
namespace {

class Statement {
 public:
  Statement(sqlite3* db, const char* sql, const std::string& path) : path_(path) {
    if (sqlite3_prepare_v2(db, sql, -1, &s_, nullptr) != SQLITE_OK) {
      const std::string m = sqlite3_errmsg(db);
      sqlite3_finalize(s_);
      throw InputError(path + ": not a rosbag2 sqlite3 bag (" + m + ")");
    }
  }
  ~Statement() { sqlite3_finalize(s_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  sqlite3_stmt* get() { return s_; }
  // True for a row, false when done. \throws InputError for an error
  bool step() {
    const int rc = sqlite3_step(s_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    throw InputError(path_ + ": damaged bag (" + sqlite3_errstr(rc) + ")");
  }
  std::string text(int col) {
    const unsigned char* t = sqlite3_column_text(s_, col);
    const int n = sqlite3_column_bytes(s_, col);
    return t ? std::string(reinterpret_cast<const char*>(t), static_cast<std::size_t>(n))
             : std::string();
  }

 private:
  sqlite3_stmt* s_ = nullptr;
  const std::string& path_;
};

class SqliteBag : public BagReader {
 public:
  explicit SqliteBag(const std::string& path) : path_(path) {
    requireRegularFile(path);  // sqlite3 would block opening a FIFO
    // Read-only and immutable: no journal, no lock files beside a bag on read-only media.
    std::string uri = "file:";
    for (unsigned char c : path) {
      if (!(std::isalnum(c) || c == '/' || c == '.' || c == '-' || c == '_' || c == '~')) {
        char buf[4];
        std::snprintf(buf, sizeof buf, "%%%02X", c);
        uri += buf;
      } else {
        uri += static_cast<char>(c);
      }
    }
    uri += "?immutable=1";
    if (sqlite3_open_v2(uri.c_str(), &db_, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr) !=
        SQLITE_OK) {
      const std::string m = db_ ? sqlite3_errmsg(db_) : "out of memory";
      sqlite3_close(db_);
      db_ = nullptr;
      throw InputError(path + ": cannot open as sqlite3 (" + m + ")");
    }
    try {
      load();
    } catch (...) {
      sqlite3_close(db_);
      db_ = nullptr;
      throw;
    }
  }
  ~SqliteBag() override {
    read_.reset();
    sqlite3_close(db_);
  }

  std::string format() const override { return "rosbag2-sqlite3"; }
  const std::string& path() const override { return path_; }
  const std::vector<BagTopic>& topics() const override { return topics_; }

  std::vector<BagMessageRef> index(const std::string& topic) override {
    std::int64_t id = -1;
    for (std::size_t k = 0; k < topics_.size(); ++k)
      if (topics_[k].name == topic) id = ids_[k];
    std::vector<BagMessageRef> refs;
    if (id < 0) return refs;
    Statement s(db_, "SELECT id, timestamp FROM messages WHERE topic_id = ? ORDER BY timestamp, id",
                path_);
    sqlite3_bind_int64(s.get(), 1, id);
    while (s.step()) {
      checkMemory(refs.size() + 1, sizeof(BagMessageRef), path_ + ": index of topic " + topic);
      BagMessageRef r;
      r.position = static_cast<std::uint64_t>(sqlite3_column_int64(s.get(), 0));
      r.time_ns = sqlite3_column_int64(s.get(), 1);
      refs.push_back(r);
    }
    return refs;
  }

  void read(const BagMessageRef& ref, std::vector<std::uint8_t>& out) override {
    if (!read_)
      read_ = std::make_unique<Statement>(db_, "SELECT data FROM messages WHERE id = ?", path_);
    sqlite3_stmt* s = read_->get();
    sqlite3_reset(s);
    sqlite3_bind_int64(s, 1, static_cast<sqlite3_int64>(ref.position));
    if (!read_->step())
      throw InputError(path_ + ": message " + std::to_string(ref.position) +
                       " is gone (file changed?)");
    const int n = sqlite3_column_bytes(s, 0);
    checkMemory(static_cast<std::uint64_t>(n), 1,
                path_ + ": message " + std::to_string(ref.position) + " of " + std::to_string(n) +
                    " bytes");
    const void* p = sqlite3_column_blob(s, 0);
    out.assign(static_cast<const std::uint8_t*>(p),
               static_cast<const std::uint8_t*>(p) + (p ? n : 0));
    sqlite3_reset(s);
  }

 private:
  void load() {
    Statement t(db_, "SELECT id, name, type, serialization_format FROM topics ORDER BY id", path_);
    while (t.step()) {
      checkMemory(topics_.size() + 1, 256, path_ + ": topics");
      BagTopic topic;
      ids_.push_back(sqlite3_column_int64(t.get(), 0));
      topic.name = t.text(1);
      topic.type = t.text(2);
      topic.encoding = t.text(3);
      topics_.push_back(std::move(topic));
    }
    Statement m(db_,
                "SELECT topic_id, COUNT(*), MIN(timestamp), MAX(timestamp) FROM messages "
                "GROUP BY topic_id",
                path_);
    while (m.step()) {
      const std::int64_t id = sqlite3_column_int64(m.get(), 0);
      for (std::size_t k = 0; k < ids_.size(); ++k) {
        if (ids_[k] != id) continue;
        topics_[k].messages = static_cast<std::uint64_t>(sqlite3_column_int64(m.get(), 1));
        topics_[k].first_ns = sqlite3_column_int64(m.get(), 2);
        topics_[k].last_ns = sqlite3_column_int64(m.get(), 3);
      }
    }
  }

  std::string path_;
  sqlite3* db_ = nullptr;
  std::vector<BagTopic> topics_;
  std::vector<std::int64_t> ids_;
  std::unique_ptr<Statement> read_;
};

}  // namespace

std::unique_ptr<BagReader> openRosbag2Sqlite(const std::string& path) {
  return std::make_unique<SqliteBag>(path);
}

}  // namespace metricmap
