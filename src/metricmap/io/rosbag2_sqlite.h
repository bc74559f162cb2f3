#pragma once
/// \file rosbag2_sqlite.h
/// \brief rosbag2's sqlite3 storage (.db3): the `topics` table (id, name, type,
/// serialization_format) and the `messages` table (id, topic_id, timestamp, data: the CDR
/// payload), read through Debian's libsqlite3, opened read-only. A damaged database is
/// reported as sqlite reports it (SQLITE_CORRUPT, SQLITE_NOTADB), naming the file.

#include <memory>
#include <string>

#include "metricmap/io/bag_reader.h"

namespace metricmap {

/// \throws InputError naming the file
std::unique_ptr<BagReader> openRosbag2Sqlite(const std::string& path);

}  // namespace metricmap
