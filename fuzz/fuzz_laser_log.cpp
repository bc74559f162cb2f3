// libFuzzer target for CARMEN laser logs and the compressed line reader: the bytes, stored as
// they are (damaged gzip/bzip2 streams come from there), gzip- or bzip2-compressed here (so that
// the text behind a valid stream is fuzzed too), or compressed and then cut, are read by
// CarmenSource (forward, then back), readScanLog and a TextLineReader with small limits. Each
// must give scans or raise InputError (CapacityError past the memory budget), never crash, hang
// or allocate without bound.
#include <cstdint>
#include <sstream>
#include <string>

#include <boost/iostreams/copy.hpp>
#include <boost/iostreams/filter/bzip2.hpp>
#include <boost/iostreams/filter/gzip.hpp>
#include <boost/iostreams/filtering_stream.hpp>

#include "fuzz_common.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/datasets/carmen_source.h"
#include "metricmap/exceptions.h"
#include "metricmap/io/laser_scan.h"
#include "metricmap/io/text_stream.h"

namespace {

template <typename Compressor>
std::string compress(const std::string& text, Compressor c) {
  std::istringstream in(text);
  std::ostringstream out;
  boost::iostreams::filtering_ostream z;
  z.push(c);
  z.push(out);
  boost::iostreams::copy(in, z);  // closes z: the stream is complete
  return out.str();
}

void readSource(const std::string& path) {
  try {
    metricmap::CarmenSource source(path);
    const std::size_t n = source.size();
    const std::size_t forward = n < 16 ? n : 16;
    for (std::size_t i = 0; i < forward; ++i) (void)source.scan(i);
    (void)source.scan(n - 1);
    (void)source.scan(0);  // backwards: the log is read again
  } catch (const metricmap::InputError&) {
  } catch (const metricmap::CapacityError&) {
  }
  try {
    (void)metricmap::readScanLog(path);
  } catch (const metricmap::InputError&) {
  } catch (const metricmap::CapacityError&) {
  }
  try {
    metricmap::TextLimits limits;
    limits.max_line_bytes = 64;
    limits.max_expansion = 4;
    limits.min_expanded_bytes = 4096;
    metricmap::TextLineReader lines(path, limits);
    std::string line;
    while (lines.next(line)) {
    }
  } catch (const metricmap::InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool budget = [] {
    metricmap::setMemoryBudget(256u << 20);
    return true;
  }();
  (void)budget;
  if (size < 2) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 2, size - 2);
  std::string bytes;
  switch (data[0] % 4) {
    case 0:
      bytes = text;
      break;
    case 1:
      bytes = compress(text, boost::iostreams::gzip_compressor());
      break;
    case 2:
      bytes = compress(text, boost::iostreams::bzip2_compressor());
      break;
    default: {  // compressed, then cut after data[1]/256 of its bytes
      bytes = data[0] & 4 ? compress(text, boost::iostreams::bzip2_compressor())
                          : compress(text, boost::iostreams::gzip_compressor());
      bytes.resize(bytes.size() * data[1] / 256);
      break;
    }
  }
  const metricmap::fuzz::TempInput input(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                         bytes.size(), "laser_log", ".clf");
  readSource(input.path());
  return 0;
}
