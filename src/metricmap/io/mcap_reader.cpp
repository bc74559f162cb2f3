#include "metricmap/io/mcap_reader.h"

#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <map>

#include "metricmap/common/memory_budget.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/chunk_buffer.h"
#include "metricmap/io/input_file.h"

namespace metricmap {

const char kMcapMagic[9] = "\x89MCAP0\r\n";

namespace {

enum Op : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kDataEnd = 0x0F,
};

constexpr std::uint64_t kNotInChunk = ~std::uint64_t(0);

std::uint64_t le64(const std::uint8_t* p) {
  std::uint64_t v = 0;
  for (int k = 7; k >= 0; --k) v = (v << 8) | p[k];
  return v;
}

std::uint32_t crc32(const std::uint8_t* p, std::size_t n) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < n; ++i) c = table[(c ^ p[i]) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

// Fields of one record's content, bounded by it.
class Cursor {
 public:
  Cursor(const std::uint8_t* p, std::size_t n, const std::string* what, std::uint64_t at)
      : p_(p), n_(n), what_(what), at_(at) {}
  std::uint8_t u8() { return *take(1); }
  std::uint16_t u16() {
    const std::uint8_t* b = take(2);
    return static_cast<std::uint16_t>(b[0] | (b[1] << 8));
  }
  std::uint32_t u32() {
    const std::uint8_t* b = take(4);
    return std::uint32_t(b[0]) | (std::uint32_t(b[1]) << 8) | (std::uint32_t(b[2]) << 16) |
           (std::uint32_t(b[3]) << 24);
  }
  std::uint64_t u64() {
    const std::uint64_t lo = u32();
    return lo | (std::uint64_t(u32()) << 32);
  }
  std::string str() {
    const std::uint32_t n = u32();
    const std::uint8_t* b = take(n);
    return std::string(reinterpret_cast<const char*>(b), n);
  }
  const std::uint8_t* take(std::uint64_t k) {
    if (k > n_ - pos_)
      throw InputError(*what_ + ": damaged MCAP record at byte " + std::to_string(at_) +
                       " (a field runs past its record)");
    const std::uint8_t* b = p_ + pos_;
    pos_ += static_cast<std::size_t>(k);
    return b;
  }
  std::size_t left() const { return n_ - pos_; }
  std::size_t pos() const { return pos_; }

 private:
  const std::uint8_t* p_;
  std::size_t n_, pos_ = 0;
  const std::string* what_;
  std::uint64_t at_;
};

struct Channel {
  std::uint16_t schema = 0;
  std::string topic, encoding;
};

class McapBag : public BagReader {
 public:
  explicit McapBag(const std::string& path) : path_(path), in_(openRegularFile(path)) {
    in_.seekg(0, std::ios::end);
    size_ = static_cast<std::uint64_t>(in_.tellg());
    char m[8];
    if (size_ < 8 || !readAt(0, m, 8) || std::memcmp(m, kMcapMagic, 8) != 0)
      throw InputError(path + ": not an MCAP file (wrong magic)");
    if (!readSummary()) {
      linear_ = true;
      scan([&](std::uint16_t, const BagMessageRef&) {});
    }
    buildTopics();
  }

  std::string format() const override { return "mcap"; }
  const std::string& path() const override { return path_; }
  const std::vector<BagTopic>& topics() const override { return topics_; }

  std::vector<BagMessageRef> index(const std::string& topic) override {
    std::vector<BagMessageRef> refs;
    auto wanted = [&](std::uint16_t id) {
      auto c = channels_.find(id);
      return c != channels_.end() && c->second.topic == topic;
    };
    auto add = [&](std::uint16_t id, const BagMessageRef& r) {
      if (!wanted(id)) return;
      checkMemory(refs.size() + 1, sizeof(BagMessageRef), path_ + ": index of topic " + topic);
      refs.push_back(r);
    };
    if (linear_) {
      scan(add);
    } else {
      for (const ChunkIndex& ci : chunk_indexes_) {
        for (const auto& entry : ci.message_index) {
          const std::uint16_t id = entry.first;
          if (!wanted(id)) continue;
          readMessageIndex(ci, entry.second, [&](std::uint64_t t, std::uint64_t o) {
            BagMessageRef r;
            r.position = ci.chunk_start;
            r.offset = o;
            r.time_ns = static_cast<std::int64_t>(t);
            add(id, r);
          });
        }
      }
    }
    std::stable_sort(refs.begin(), refs.end(), [](const BagMessageRef& a, const BagMessageRef& b) {
      return a.time_ns < b.time_ns;
    });
    return refs;
  }

  void read(const BagMessageRef& ref, std::vector<std::uint8_t>& out) override {
    const std::uint8_t* rec;
    std::uint64_t len;
    std::vector<std::uint8_t> own;
    std::uint64_t at;
    if (ref.offset == kNotInChunk) {
      std::uint8_t op;
      recordAt(ref.position, op, len);
      if (op != kMessage) throw InputError(where(ref.position) + ": not a message record");
      own.resize(len);
      if (!readAt(ref.position + 9, own.data(), len)) throw truncated(ref.position);
      rec = own.data();
      at = ref.position;
    } else {
      loadChunk(ref.position);
      if (ref.offset > chunk_.size() || chunk_.size() - ref.offset < 9)
        throw InputError(where(ref.position) + ": message offset " + std::to_string(ref.offset) +
                         " is outside its chunk");
      const std::uint8_t* p = chunk_.data() + ref.offset;
      len = le64(p + 1);
      if (p[0] != kMessage || len > chunk_.size() - ref.offset - 9)
        throw InputError(where(ref.position) + ": no message record at offset " +
                         std::to_string(ref.offset) + " in the chunk");
      rec = p + 9;
      at = ref.position;
    }
    Cursor c(rec, static_cast<std::size_t>(len), &path_, at);
    c.take(2 + 4 + 8 + 8);
    const std::uint8_t* data = rec + c.pos();
    out.assign(data, data + c.left());
  }

 private:
  struct ChunkIndex {
    std::uint64_t chunk_start = 0, chunk_length = 0;
    std::vector<std::pair<std::uint16_t, std::uint64_t>> message_index;
  };

  std::string where(std::uint64_t at) const { return path_ + ": byte " + std::to_string(at); }
  InputError truncated(std::uint64_t at) const {
    return InputError(path_ + ": truncated MCAP file (a record at byte " + std::to_string(at) +
                      " runs past the end)");
  }

  bool readAt(std::uint64_t at, void* p, std::uint64_t n) {
    if (at > size_ || n > size_ - at) return false;
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(at));
    in_.read(static_cast<char*>(p), static_cast<std::streamsize>(n));
    return static_cast<std::uint64_t>(in_.gcount()) == n;
  }

  // The opcode and length of the record at `at`, its content checked to lie inside the file.
  void recordAt(std::uint64_t at, std::uint8_t& op, std::uint64_t& len) {
    std::uint8_t h[9];
    if (!readAt(at, h, 9)) throw truncated(at);
    op = h[0];
    len = 0;
    for (int k = 8; k >= 1; --k) len = (len << 8) | h[k];
    if (len > size_ - at - 9) throw truncated(at);
  }

  std::vector<std::uint8_t> content(std::uint64_t at, std::uint64_t len) {
    checkMemory(len, 1, where(at) + ": a record of " + std::to_string(len) + " bytes");
    std::vector<std::uint8_t> v(static_cast<std::size_t>(len));
    if (!readAt(at + 9, v.data(), len)) throw truncated(at);
    return v;
  }

  void schemaRecord(Cursor c) {
    const std::uint16_t id = c.u16();
    schemas_[id] = c.str();
  }
  void channelRecord(Cursor c) {
    Channel ch;
    const std::uint16_t id = c.u16();
    ch.schema = c.u16();
    ch.topic = c.str();
    ch.encoding = c.str();
    channels_[id] = std::move(ch);
  }

  // The records of the data section, in order: f(channel, ref) for every message.
  template <class F>
  void scan(F&& f) {
    std::uint64_t at = 8;
    while (at < size_) {
      std::uint8_t op;
      std::uint64_t len;
      recordAt(at, op, len);
      if (op == kFooter || op == kDataEnd) return;
      if (op == kSchema || op == kChannel) {
        const auto v = content(at, len);
        Cursor c(v.data(), v.size(), &path_, at);
        op == kSchema ? schemaRecord(c) : channelRecord(c);
      } else if (op == kMessage) {
        std::uint8_t h[22];
        if (len < 22 || !readAt(at + 9, h, 22))
          throw InputError(where(at) + ": short message record");
        Cursor c(h, 22, &path_, at);
        const std::uint16_t channel = c.u16();
        c.u32();
        BagMessageRef r;
        r.position = at;
        r.offset = kNotInChunk;
        r.time_ns = static_cast<std::int64_t>(c.u64());
        count(channel, r.time_ns);
        f(channel, r);
      } else if (op == kChunk) {
        loadChunk(at);
        std::uint64_t k = 0;
        while (k < chunk_.size()) {
          if (chunk_.size() - k < 9) throw InputError(where(at) + ": a chunk ends inside a record");
          const std::uint8_t* p = chunk_.data() + k;
          const std::uint64_t n = le64(p + 1);
          if (n > chunk_.size() - k - 9)
            throw InputError(where(at) + ": a record in the chunk runs past its end");
          Cursor c(p + 9, static_cast<std::size_t>(n), &path_, at);
          if (p[0] == kSchema) schemaRecord(c);
          if (p[0] == kChannel) channelRecord(c);
          if (p[0] == kMessage) {
            const std::uint16_t channel = c.u16();
            c.u32();
            BagMessageRef r;
            r.position = at;
            r.offset = k;
            r.time_ns = static_cast<std::int64_t>(c.u64());
            count(channel, r.time_ns);
            f(channel, r);
          }
          k += 9 + n;
        }
      }
      at += 9 + len;
    }
    throw InputError(path_ + ": truncated MCAP file (no Footer record)");
  }

  void count(std::uint16_t channel, std::int64_t t) {
    if (counted_) return;
    auto& s = stats_[channel];
    if (s.messages == 0 || t < s.first_ns) s.first_ns = t;
    if (s.messages == 0 || t > s.last_ns) s.last_ns = t;
    ++s.messages;
  }

  // Decompress the chunk at `at` into chunk_ (kept for the next read).
  void loadChunk(std::uint64_t at) {
    if (chunk_at_ == at) return;
    chunk_at_ = ~std::uint64_t(0);
    std::uint8_t op;
    std::uint64_t len;
    recordAt(at, op, len);
    if (op != kChunk) throw InputError(where(at) + ": not a chunk record");
    const auto v = content(at, len);
    Cursor c(v.data(), v.size(), &path_, at);
    c.u64();
    c.u64();
    const std::uint64_t usize = c.u64();
    const std::uint32_t crc = c.u32();
    const std::string compression = c.str();
    const std::uint64_t csize = c.u64();
    if (csize != c.left())
      throw InputError(where(at) + ": chunk says " + std::to_string(csize) +
                       " compressed bytes, its record holds " + std::to_string(c.left()));
    const std::uint8_t* src = c.take(csize);
    if (compression.empty() && csize != usize)
      throw InputError(where(at) + ": uncompressed chunk of " + std::to_string(csize) +
                       " bytes says " + std::to_string(usize));
    checkMemory(usize, 1, where(at) + ": a chunk of " + std::to_string(usize) + " bytes");
    chunk_.resize(static_cast<std::size_t>(usize));
    if (compression.empty()) {
      if (usize > 0) std::memcpy(chunk_.data(), src, usize);  // an empty chunk has no buffer
    } else if (compression == "zstd") {
      const std::size_t n = ZSTD_decompress(chunk_.data(), chunk_.size(), src, csize);
      if (ZSTD_isError(n) || n != usize)
        throw InputError(where(at) + ": damaged zstd chunk (" +
                         (ZSTD_isError(n)
                              ? std::string(ZSTD_getErrorName(n))
                              : std::to_string(n) + " bytes, not " + std::to_string(usize)) +
                         ")");
    } else if (compression == "lz4") {
      LZ4F_dctx* ctx = nullptr;
      if (LZ4F_isError(LZ4F_createDecompressionContext(&ctx, LZ4F_VERSION)))
        throw InputError(where(at) + ": cannot start lz4");
      std::size_t out = 0, in = 0;
      std::size_t r = 1;
      while (in < csize && r != 0) {
        std::size_t dn = chunk_.size() - out, sn = csize - in;
        r = LZ4F_decompress(ctx, chunk_.data() + out, &dn, src + in, &sn, nullptr);
        if (LZ4F_isError(r)) break;
        out += dn;
        in += sn;
        if (dn == 0 && sn == 0) break;
        if (out == chunk_.size() && r != 0) {
          // More output than declared: probe one byte.
          std::uint8_t probe;
          std::size_t pn = 1, psn = csize - in;
          const std::size_t r2 = LZ4F_decompress(ctx, &probe, &pn, src + in, &psn, nullptr);
          if (!LZ4F_isError(r2) && pn > 0) out = chunk_.size() + 1;
          r = LZ4F_isError(r2) ? r2 : 0;
          break;
        }
      }
      const bool bad = LZ4F_isError(r) || r != 0 || out != usize;
      const std::string why = LZ4F_isError(r) ? LZ4F_getErrorName(r) : "wrong size";
      LZ4F_freeDecompressionContext(ctx);
      if (bad) throw InputError(where(at) + ": damaged lz4 chunk (" + why + ")");
    } else {
      throw InputError(where(at) + ": unknown chunk compression '" + compression + "'");
    }
    if (crc != 0 && crc32(chunk_.data(), chunk_.size()) != crc)
      throw InputError(where(at) + ": chunk CRC mismatch");
    chunk_at_ = at;
  }

  // Footer -> summary section. False when there is none usable (then: linear scan).
  bool readSummary() {
    if (size_ < 8 + 9 + 20 + 8) return false;
    char m[8];
    const std::uint64_t footer = size_ - 8 - 9 - 20;
    if (!readAt(size_ - 8, m, 8) || std::memcmp(m, kMcapMagic, 8) != 0) return false;
    std::uint8_t f[29];
    if (!readAt(footer, f, 29) || f[0] != kFooter) return false;
    Cursor fc(f + 9, 20, &path_, footer);
    const std::uint64_t summary = fc.u64();
    if (summary == 0 || summary < 8 || summary >= footer) return false;
    std::vector<ChunkIndex> cis;
    for (std::uint64_t at = summary; at < footer;) {
      std::uint8_t op;
      std::uint64_t len;
      recordAt(at, op, len);
      if (len > footer - at - 9) throw truncated(at);
      if (op == kSchema || op == kChannel || op == kChunkIndex) {
        const auto v = content(at, len);
        Cursor c(v.data(), v.size(), &path_, at);
        if (op == kSchema) schemaRecord(c);
        if (op == kChannel) channelRecord(c);
        if (op == kChunkIndex) {
          checkMemory(cis.size() + 1, 64, path_ + ": chunk indexes");
          ChunkIndex ci;
          c.u64();
          c.u64();
          ci.chunk_start = c.u64();
          ci.chunk_length = c.u64();
          const std::uint32_t n = c.u32();
          Cursor m(c.take(n), n, &path_, at);
          while (m.left() > 0) {
            const std::uint16_t id = m.u16();
            ci.message_index.emplace_back(id, m.u64());
          }
          if (ci.chunk_start < 8 || ci.chunk_start > size_ ||
              ci.chunk_length > size_ - ci.chunk_start)
            throw InputError(where(at) + ": chunk index points outside the file");
          if (ci.message_index.empty()) return false;  // no message indexes: scan
          cis.push_back(std::move(ci));
        }
      }
      at += 9 + len;
    }
    if (cis.empty()) return false;
    chunk_indexes_ = std::move(cis);
    for (const ChunkIndex& ci : chunk_indexes_)
      for (const auto& [id, offset] : ci.message_index)
        readMessageIndex(ci, offset, [&, id = id](std::uint64_t t, std::uint64_t) {
          count(id, static_cast<std::int64_t>(t));
        });
    return true;
  }

  template <class F>
  void readMessageIndex(const ChunkIndex& ci, std::uint64_t at, F&& f) {
    std::uint8_t op;
    std::uint64_t len;
    recordAt(at, op, len);
    if (op != kMessageIndex) throw InputError(where(at) + ": not a message index record");
    const auto v = content(at, len);
    Cursor c(v.data(), v.size(), &path_, at);
    c.u16();
    const std::uint32_t n = c.u32();
    if (n % 16 != 0 || n != c.left())
      throw InputError(where(at) + ": message index of " + std::to_string(n) + " bytes");
    (void)ci;
    for (std::uint32_t k = 0; k < n / 16; ++k) {
      const std::uint64_t t = c.u64();
      f(t, c.u64());
    }
  }

  void buildTopics() {
    counted_ = true;
    for (const auto& [id, ch] : channels_) {
      BagTopic t;
      t.name = ch.topic;
      auto s = schemas_.find(ch.schema);
      t.type = s == schemas_.end() ? std::string() : s->second;
      t.encoding = ch.encoding;
      auto st = stats_.find(id);
      if (st != stats_.end()) {
        t.messages = st->second.messages;
        t.first_ns = st->second.first_ns;
        t.last_ns = st->second.last_ns;
      }
      // Two channels on one topic (two publishers) are one topic.
      auto same = std::find_if(topics_.begin(), topics_.end(),
                               [&](const BagTopic& x) { return x.name == t.name; });
      if (same == topics_.end()) {
        topics_.push_back(std::move(t));
      } else if (t.messages > 0) {
        if (same->messages == 0 || t.first_ns < same->first_ns) same->first_ns = t.first_ns;
        if (same->messages == 0 || t.last_ns > same->last_ns) same->last_ns = t.last_ns;
        same->messages += t.messages;
      }
    }
  }

  std::string path_;
  std::ifstream in_;
  std::uint64_t size_ = 0;
  bool linear_ = false, counted_ = false;
  std::map<std::uint16_t, std::string> schemas_;
  std::map<std::uint16_t, Channel> channels_;
  std::map<std::uint16_t, BagTopic> stats_;
  std::vector<ChunkIndex> chunk_indexes_;
  detail::ChunkBuffer chunk_;  // not zeroed: see chunk_buffer.h
  std::uint64_t chunk_at_ = ~std::uint64_t(0);
  std::vector<BagTopic> topics_;
};

}  // namespace

std::unique_ptr<BagReader> openMcap(const std::string& path) {
  return std::make_unique<McapBag>(path);
}

}  // namespace metricmap
