// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "mapCache.h"

namespace reparam {

namespace {

  // FNV-1a over the patch's coordinates and triangles, from two seeds (two
  // independent 64-bit hashes: a collision would hand a patch another's map)
  void hashOf(const discretePatch &patch, std::uint64_t hash[2])
  {
    const std::uint64_t seeds[2] = {1469598103934665603ull,
                                    0x9e3779b97f4a7c15ull};
    for(int k = 0; k < 2; k++) {
      std::uint64_t h = seeds[k];
      auto add = [&h](const void *data, std::size_t bytes) {
        const unsigned char *c = (const unsigned char *)data;
        for(std::size_t i = 0; i < bytes; i++)
          h = (h ^ c[i]) * 1099511628211ull;
      };
      for(const SPoint3 &p : patch.points) add(p.data(), 3 * sizeof(double));
      add(patch.triangles.data(),
          patch.triangles.size() * sizeof(std::array<int, 3>));
      hash[k] = h;
    }
  }

} // namespace

bool mapCache::key::operator==(const key &other) const
{
  return points == other.points && triangles == other.triangles &&
         hash[0] == other.hash[0] && hash[1] == other.hash[1] &&
         choice == other.choice && repair == other.repair;
}

mapCache::key mapCache::keyOf(const discretePatch &patch, int choice,
                              bool repair)
{
  key k;
  k.points = patch.points.size();
  k.triangles = patch.triangles.size();
  hashOf(patch, k.hash);
  k.choice = choice;
  k.repair = repair;
  return k;
}

void mapCache::keep(const discretePatch &patch, int choice, bool repair,
                    const checkedMap &result)
{
  entry e{keyOf(patch, choice, repair), result};
  std::lock_guard<std::mutex> lock(_lock);
  _entries.push_back(std::move(e));
}

bool mapCache::take(const discretePatch &patch, int choice, bool repair,
                    checkedMap &result)
{
  const key k = keyOf(patch, choice, repair);
  std::lock_guard<std::mutex> lock(_lock);
  for(std::size_t i = 0; i < _entries.size(); i++) {
    if(!(_entries[i].of == k)) continue;
    result = std::move(_entries[i].result);
    _entries.erase(_entries.begin() + i);
    return true;
  }
  return false;
}

void mapCache::clear()
{
  std::lock_guard<std::mutex> lock(_lock);
  _entries.clear();
}

std::size_t mapCache::size() const
{
  std::lock_guard<std::mutex> lock(_lock);
  return _entries.size();
}

} // namespace reparam
