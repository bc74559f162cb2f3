#include "metricmap/io/rosbag1_reader.h"

#include <bzlib.h>
#include <lz4frame.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <map>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/chunk_buffer.h"
#include "metricmap/io/input_file.h"

namespace metricmap {
namespace {

constexpr char kMagic[] = "#ROSBAG V2.0\n";
constexpr std::size_t kMagicSize = 13;
constexpr std::uint64_t kTopLevel = ~std::uint64_t(0);

enum Op : std::uint8_t {
  kMessageData = 0x02,
  kBagHeader = 0x03,
  kChunk = 0x05,
  kConnection = 0x07,
};

std::uint32_t le32(const std::uint8_t* p) {
  return std::uint32_t(p[0]) | (std::uint32_t(p[1]) << 8) | (std::uint32_t(p[2]) << 16) |
         (std::uint32_t(p[3]) << 24);
}

// The `name=value` fields of a record header (or a connection header).
std::map<std::string, std::string> fields(const std::uint8_t* p, std::size_t n,
                                          const std::string& where) {
  std::map<std::string, std::string> f;
  std::size_t at = 0;
  while (at < n) {
    if (n - at < 4) throw InputError(where + ": a header field's length is cut off");
    const std::uint32_t len = le32(p + at);
    at += 4;
    if (len > n - at) throw InputError(where + ": a header field runs past its header");
    const char* s = reinterpret_cast<const char*>(p + at);
    const void* eq = std::memchr(s, '=', len);
    if (!eq) throw InputError(where + ": a header field without '='");
    const std::size_t k = static_cast<std::size_t>(static_cast<const char*>(eq) - s);
    f[std::string(s, k)] = std::string(s + k + 1, len - k - 1);
    at += len;
  }
  return f;
}

const std::string& field(const std::map<std::string, std::string>& f, const char* name,
                         std::size_t size, const std::string& where) {
  auto it = f.find(name);
  if (it == f.end()) throw InputError(where + ": record without its '" + name + "' field");
  if (size && it->second.size() != size)
    throw InputError(where + ": field '" + name + "' of " + std::to_string(it->second.size()) +
                     " bytes, not " + std::to_string(size));
  return it->second;
}

std::uint32_t u32Field(const std::map<std::string, std::string>& f, const char* name,
                       const std::string& where) {
  return le32(reinterpret_cast<const std::uint8_t*>(field(f, name, 4, where).data()));
}

struct Connection {
  std::string topic, type;
};

class Rosbag1 : public BagReader {
 public:
  explicit Rosbag1(const std::string& path) : path_(path), in_(openRegularFile(path)) {
    in_.seekg(0, std::ios::end);
    size_ = static_cast<std::uint64_t>(in_.tellg());
    char m[kMagicSize];
    if (size_ < kMagicSize || !readAt(0, m, kMagicSize) || std::memcmp(m, kMagic, kMagicSize) != 0)
      throw InputError(path + ": not a ROS 1 bag (wrong magic)");
    scan([](std::uint32_t, const BagMessageRef&) {});
    for (const auto& [id, c] : connections_) {
      auto same =
          std::find_if(topics_.begin(), topics_.end(),
                       [&, &topic = c.topic](const BagTopic& t) { return t.name == topic; });
      BagTopic t;
      t.name = c.topic;
      t.type = c.type;
      t.encoding = "ros1";
      auto st = stats_.find(id);
      if (st != stats_.end()) t = mergeStats(t, st->second);
      if (same == topics_.end()) {
        topics_.push_back(t);
      } else if (st != stats_.end()) {
        *same = mergeStats(*same, st->second);
      }
    }
    counted_ = true;
  }

  std::string format() const override { return "rosbag1"; }
  const std::string& path() const override { return path_; }
  const std::vector<BagTopic>& topics() const override { return topics_; }

  std::vector<BagMessageRef> index(const std::string& topic) override {
    std::vector<BagMessageRef> refs;
    scan([&](std::uint32_t conn, const BagMessageRef& r) {
      auto c = connections_.find(conn);
      if (c == connections_.end() || c->second.topic != topic) return;
      checkMemory(refs.size() + 1, sizeof(BagMessageRef), path_ + ": index of topic " + topic);
      refs.push_back(r);
    });
    std::stable_sort(refs.begin(), refs.end(), [](const BagMessageRef& a, const BagMessageRef& b) {
      return a.time_ns < b.time_ns;
    });
    return refs;
  }

  void read(const BagMessageRef& ref, std::vector<std::uint8_t>& out) override {
    if (ref.offset == kTopLevel) {
      Record r = recordAt(ref.position);
      const auto data = bytes(r.data_at, r.data_len, ref.position);
      out.assign(data.begin(), data.end());
      return;
    }
    loadChunk(ref.position);
    const std::string where = at(ref.position) + " (chunk), offset " + std::to_string(ref.offset);
    std::size_t k = static_cast<std::size_t>(ref.offset);
    if (k > chunk_.size() || chunk_.size() - k < 4) throw InputError(where + ": outside its chunk");
    const std::uint32_t hl = le32(chunk_.data() + k);
    if (hl > chunk_.size() - k - 4 || chunk_.size() - k - 4 - hl < 4)
      throw InputError(where + ": a record runs past its chunk");
    const std::uint32_t dl = le32(chunk_.data() + k + 4 + hl);
    if (dl > chunk_.size() - k - 8 - hl) throw InputError(where + ": a record runs past its chunk");
    const std::uint8_t* d = chunk_.data() + k + 8 + hl;
    out.assign(d, d + dl);
  }

 private:
  struct Record {
    std::map<std::string, std::string> header;
    std::uint64_t data_at = 0, data_len = 0, end = 0;
    std::uint8_t op = 0;
  };

  static BagTopic mergeStats(BagTopic t, const BagTopic& s) {
    if (s.messages == 0) return t;
    if (t.messages == 0 || s.first_ns < t.first_ns) t.first_ns = s.first_ns;
    if (t.messages == 0 || s.last_ns > t.last_ns) t.last_ns = s.last_ns;
    t.messages += s.messages;
    return t;
  }

  std::string at(std::uint64_t pos) const { return path_ + ": byte " + std::to_string(pos); }

  bool readAt(std::uint64_t pos, void* p, std::uint64_t n) {
    if (pos > size_ || n > size_ - pos) return false;
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(pos));
    in_.read(static_cast<char*>(p), static_cast<std::streamsize>(n));
    return static_cast<std::uint64_t>(in_.gcount()) == n;
  }

  std::vector<std::uint8_t> bytes(std::uint64_t pos, std::uint64_t n, std::uint64_t record) {
    checkMemory(n, 1, at(record) + ": a record of " + std::to_string(n) + " bytes");
    std::vector<std::uint8_t> v(static_cast<std::size_t>(n));
    if (!readAt(pos, v.data(), n)) throw truncated(record);
    return v;
  }

  InputError truncated(std::uint64_t pos) const {
    return InputError(path_ + ": truncated ROS 1 bag (a record at byte " + std::to_string(pos) +
                      " runs past the end)");
  }

  Record recordAt(std::uint64_t pos) {
    std::uint8_t b[4];
    if (!readAt(pos, b, 4)) throw truncated(pos);
    const std::uint32_t hl = le32(b);
    if (hl > size_ - pos - 4) throw truncated(pos);
    Record r;
    const auto h = bytes(pos + 4, hl, pos);
    r.header = fields(h.data(), h.size(), at(pos));
    r.op = static_cast<std::uint8_t>(field(r.header, "op", 1, at(pos))[0]);
    if (!readAt(pos + 4 + hl, b, 4)) throw truncated(pos);
    r.data_len = le32(b);
    r.data_at = pos + 8 + hl;
    if (r.data_len > size_ - r.data_at) throw truncated(pos);
    r.end = r.data_at + r.data_len;
    return r;
  }

  void connection(const std::map<std::string, std::string>& h, const std::uint8_t* data,
                  std::size_t n, const std::string& where) {
    Connection c;
    const std::uint32_t id = u32Field(h, "conn", where);
    c.topic = field(h, "topic", 0, where);
    const auto d = fields(data, n, where + " (connection header)");
    c.type = field(d, "type", 0, where + " (connection header)");
    connections_[id] = std::move(c);
  }

  std::int64_t time(const std::map<std::string, std::string>& h, const std::string& where) {
    const auto* t = reinterpret_cast<const std::uint8_t*>(field(h, "time", 8, where).data());
    return std::int64_t(le32(t)) * 1000000000 + std::int64_t(le32(t + 4));
  }

  void count(std::uint32_t conn, std::int64_t t) {
    if (counted_) return;
    BagTopic& s = stats_[conn];
    if (s.messages == 0 || t < s.first_ns) s.first_ns = t;
    if (s.messages == 0 || t > s.last_ns) s.last_ns = t;
    ++s.messages;
  }

  template <class F>
  void scan(F&& f) {
    std::uint64_t pos = kMagicSize;
    bool header = false;
    while (pos < size_) {
      const Record r = recordAt(pos);
      const std::string where = at(pos);
      if (!header && r.op != kBagHeader) throw InputError(where + ": no bag header record first");
      header = true;
      if (r.op == kConnection) {
        const auto d = bytes(r.data_at, r.data_len, pos);
        connection(r.header, d.data(), d.size(), where);
      } else if (r.op == kMessageData) {
        BagMessageRef m;
        m.position = pos;
        m.offset = kTopLevel;
        m.time_ns = time(r.header, where);
        const std::uint32_t conn = u32Field(r.header, "conn", where);
        count(conn, m.time_ns);
        f(conn, m);
      } else if (r.op == kChunk) {
        loadChunk(pos);
        std::size_t k = 0;
        while (k < chunk_.size()) {
          const std::string w = where + " (chunk), offset " + std::to_string(k);
          if (chunk_.size() - k < 4) throw InputError(w + ": a record is cut off");
          const std::uint32_t hl = le32(chunk_.data() + k);
          if (hl > chunk_.size() - k - 4 || chunk_.size() - k - 4 - hl < 4)
            throw InputError(w + ": a record runs past its chunk");
          const auto h = fields(chunk_.data() + k + 4, hl, w);
          const std::uint32_t dl = le32(chunk_.data() + k + 4 + hl);
          if (dl > chunk_.size() - k - 8 - hl)
            throw InputError(w + ": a record runs past its chunk");
          const std::uint8_t op = static_cast<std::uint8_t>(field(h, "op", 1, w)[0]);
          if (op == kConnection) connection(h, chunk_.data() + k + 8 + hl, dl, w);
          if (op == kMessageData) {
            BagMessageRef m;
            m.position = pos;
            m.offset = k;
            m.time_ns = time(h, w);
            const std::uint32_t conn = u32Field(h, "conn", w);
            count(conn, m.time_ns);
            f(conn, m);
          }
          k += 8 + hl + dl;
        }
      }
      pos = r.end;
    }
  }

  void loadChunk(std::uint64_t pos) {
    if (chunk_at_ == pos) return;
    chunk_at_ = kTopLevel;
    const Record r = recordAt(pos);
    const std::string where = at(pos);
    if (r.op != kChunk) throw InputError(where + ": not a chunk record");
    const std::string& compression = field(r.header, "compression", 0, where);
    const std::uint32_t usize = u32Field(r.header, "size", where);
    const auto src = bytes(r.data_at, r.data_len, pos);
    if (compression == "none" && src.size() != usize)
      throw InputError(where + ": uncompressed chunk of " + std::to_string(src.size()) +
                       " bytes says " + std::to_string(usize));
    checkMemory(usize, 1, where + ": a chunk of " + std::to_string(usize) + " bytes");
    chunk_.resize(usize);
    if (compression == "none") {
      std::copy(src.begin(), src.end(), chunk_.begin());
    } else if (compression == "bz2") {
      unsigned int n = usize;
      std::vector<char> in(src.begin(), src.end());  // libbz2 takes non-const input
      const int rc =
          BZ2_bzBuffToBuffDecompress(reinterpret_cast<char*>(chunk_.data()), &n, in.data(),
                                     static_cast<unsigned int>(in.size()), 0, 0);
      if (rc != BZ_OK || n != usize)
        throw InputError(where + ": damaged bz2 chunk (" +
                         (rc != BZ_OK
                              ? "libbz2 error " + std::to_string(rc)
                              : std::to_string(n) + " bytes, not " + std::to_string(usize)) +
                         ")");
    } else if (compression == "lz4") {
      LZ4F_dctx* ctx = nullptr;
      if (LZ4F_isError(LZ4F_createDecompressionContext(&ctx, LZ4F_VERSION)))
        throw InputError(where + ": cannot start lz4");
      std::size_t out = 0, in = 0, r2 = 1;
      while (in < src.size() && r2 != 0) {
        std::size_t dn = chunk_.size() - out, sn = src.size() - in;
        r2 = LZ4F_decompress(ctx, chunk_.data() + out, &dn, src.data() + in, &sn, nullptr);
        if (LZ4F_isError(r2)) break;
        out += dn;
        in += sn;
        if (dn == 0 && sn == 0) break;
      }
      const bool bad = LZ4F_isError(r2) || r2 != 0 || out != usize;
      const std::string why = LZ4F_isError(r2) ? LZ4F_getErrorName(r2) : "wrong size";
      LZ4F_freeDecompressionContext(ctx);
      if (bad) throw InputError(where + ": damaged lz4 chunk (" + why + ")");
    } else {
      throw InputError(where + ": unknown chunk compression '" + compression + "'");
    }
    chunk_at_ = pos;
  }

  std::string path_;
  std::ifstream in_;
  std::uint64_t size_ = 0;
  bool counted_ = false;
  std::map<std::uint32_t, Connection> connections_;
  std::map<std::uint32_t, BagTopic> stats_;
  std::vector<BagTopic> topics_;
  detail::ChunkBuffer chunk_;  // not zeroed: see chunk_buffer.h
  std::uint64_t chunk_at_ = kTopLevel;
};

}  // namespace

std::unique_ptr<BagReader> openRosbag1(const std::string& path) {
  return std::make_unique<Rosbag1>(path);
}

}  // namespace metricmap
