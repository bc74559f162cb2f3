#pragma once
// Tests that read ../shared/data: skipped (reported as skipped by ctest) where the data is
// missing, failed where METRICMAP_REQUIRE_SHARED_DATA=1 (scripts/test sets it when ../shared/data
// exists, so CI never passes a data test by skipping it).
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

inline bool sharedDataRequired() {
  const char* v = std::getenv("METRICMAP_REQUIRE_SHARED_DATA");
  return v != nullptr && std::string(v) == "1";
}

#define SKIP_WITHOUT_SHARED_DATA(path)                                       \
  do {                                                                       \
    if (!std::filesystem::exists(path)) {                                    \
      if (sharedDataRequired())                                              \
        FAIL() << (path) << " is missing (METRICMAP_REQUIRE_SHARED_DATA=1)"; \
      GTEST_SKIP() << (path) << " is missing";                               \
    }                                                                        \
  } while (0)
