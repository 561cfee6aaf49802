// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Maps computed once and taken again: the patch layout verifies each part
// with the map CreateGeometry will compute for it, so CreateGeometry takes
// the layout's result instead of solving the same patch twice. An entry
// matches a patch equal to the last bit (same nodes, coordinates and
// triangles, in the same order), the same map choice and repair option,
// and is used once. Thread-safe: the layout verifies parts on several
// threads.

#ifndef REPARAM_MAP_CACHE_H
#define REPARAM_MAP_CACHE_H

#include <cstdint>
#include <mutex>
#include <vector>
#include "discretePatch.h"
#include "mapChain.h"

namespace reparam {

class mapCache {
public:
  // Keeps `result`, the chain's map of `patch` for (choice, repair)
  void keep(const discretePatch &patch, int choice, bool repair,
            const checkedMap &result);
  // Takes the map kept for the same patch, choice and repair (removing
  // it); false if there is none
  bool take(const discretePatch &patch, int choice, bool repair,
            checkedMap &result);
  void clear();
  std::size_t size() const;

private:
  struct key {
    std::size_t points = 0, triangles = 0;
    std::uint64_t hash[2] = {0, 0};
    int choice = -1;
    bool repair = false;
    bool operator==(const key &other) const;
  };
  struct entry {
    key of;
    checkedMap result;
  };
  static key keyOf(const discretePatch &patch, int choice, bool repair);
  mutable std::mutex _lock;
  std::vector<entry> _entries;
};

} // namespace reparam

#endif
