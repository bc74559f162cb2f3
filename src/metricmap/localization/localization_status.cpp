#include "metricmap/localization/localization_status.h"

namespace metricmap {

const char* statusName(LocalizationStatus status) {
  switch (status) {
    case LocalizationStatus::NotFound:
      return "not_found";
    case LocalizationStatus::Ambiguous:
      return "ambiguous";
    case LocalizationStatus::Waiting:
      return "waiting";
    case LocalizationStatus::Fixed:
      return "fixed";
    case LocalizationStatus::Tracked:
      return "tracked";
    case LocalizationStatus::Weak:
      return "weak";
    case LocalizationStatus::Lost:
      return "lost";
  }
  return "unknown";
}

}  // namespace metricmap
