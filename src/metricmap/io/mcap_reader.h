#pragma once
/// \file mcap_reader.h
/// \brief MCAP files (https://mcap.dev/spec), read from the specification: the magic at both
/// ends, records (opcode, u64 length, content), Schema/Channel/Message records, Chunks
/// (uncompressed, lz4 frames or zstd, via Debian's liblz4/libzstd; the uncompressed CRC-32 is
/// checked when non-zero). With a summary section (Footer -> Schemas, Channels, Chunk Indexes,
/// each chunk's Message Index records) a topic is indexed without decompressing a chunk;
/// without one (or when its chunk indexes carry no message indexes) the data section is
/// scanned record by record. Memory: one chunk at a time (its declared uncompressed size,
/// checked against the budget and against the file) plus the selected topic's index.

#include <memory>
#include <string>

#include "metricmap/io/bag_reader.h"

namespace metricmap {

/// \brief The 8 bytes an MCAP file starts and ends with.
extern const char kMcapMagic[9];

/// \throws InputError naming the file (and the byte offset) when it is not MCAP or is damaged
std::unique_ptr<BagReader> openMcap(const std::string& path);

}  // namespace metricmap
