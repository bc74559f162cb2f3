#include "metricmap/common/cell_table.h"

namespace metricmap {

CellTable::CellTable(std::size_t expected) {
  int bits = 4;
  while ((std::size_t{1} << bits) < 2 * expected) ++bits;
  slots_.assign(std::size_t{1} << bits, Slot{kEmpty, 0});
  shift_ = 64 - bits;
}

std::size_t CellTable::findOrInsert(std::uint64_t key, std::size_t new_id) {
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t s = slotOf(key);; s = (s + 1) & mask) {
    Slot& slot = slots_[s];
    if (slot.key == key) return static_cast<std::size_t>(slot.id);
    if (slot.key == kEmpty) {
      slot = Slot{key, new_id};
      if (2 * ++size_ > slots_.size()) grow();
      return new_id;
    }
  }
}

void CellTable::grow() {
  std::vector<Slot> old;
  old.swap(slots_);
  slots_.assign(old.size() * 2, Slot{kEmpty, 0});
  --shift_;
  const std::size_t mask = slots_.size() - 1;
  for (const Slot& o : old) {
    if (o.key == kEmpty) continue;
    std::size_t s = slotOf(o.key);
    while (slots_[s].key != kEmpty) s = (s + 1) & mask;
    slots_[s] = o;
  }
}

std::vector<std::pair<std::uint64_t, std::size_t>> CellTable::entries() const {
  std::vector<std::pair<std::uint64_t, std::size_t>> out;
  out.reserve(size_);
  for (const Slot& s : slots_) {
    if (s.key != kEmpty) out.emplace_back(s.key, static_cast<std::size_t>(s.id));
  }
  return out;
}

}  // namespace metricmap
