// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <thread>
#include "SVector3.h"
#include "featureScale.h"
#include "patchLayout.h"
#include "stageTimer.h"
#include "triangleAdjacency.h"
#include "unpinchCut.h"

namespace reparam {

double triangleArea(const layoutMesh &mesh, int t)
{
  const auto &tri = mesh.triangles[t];
  SVector3 n = crossprod(SVector3(mesh.points[tri[0]], mesh.points[tri[1]]),
                         SVector3(mesh.points[tri[0]], mesh.points[tri[2]]));
  return 0.5 * n.norm();
}

double edgeLength(const layoutMesh &mesh, const std::array<int, 2> &edge)
{
  return mesh.points[edge[0]].distance(mesh.points[edge[1]]);
}

namespace {

  std::vector<char> featureEdgeFlags(const layoutMesh &mesh,
                                     const triangleAdjacency &adjacency)
  {
    std::vector<char> flags(adjacency.edges.size(), 0);
    for(const auto &f : mesh.featureEdges) {
      int e = adjacency.find(f[0], f[1]);
      if(e >= 0) flags[e] = 1;
    }
    return flags;
  }

  // A part waiting for its verification; path: where it comes from (the
  // index of its feature patch, then of each part it was cut from), which
  // orders the final patches the same whatever the order parts are verified
  // in, and so on any number of threads
  struct pendingPart {
    std::vector<int> triangles;
    int depth;
    std::vector<int> path;
  };

  // What became of a part: cut into parts, or kept as a patch (verified or
  // not)
  struct partOutcome {
    std::vector<pendingPart> parts;
    bool split = false; // by bisectPart, else into its components
    layoutSplit record;
    bool kept = false;
    partCheck check;
  };

  pendingPart childOf(const pendingPart &part, std::vector<int> triangles,
                      int depth, int index)
  {
    pendingPart child{std::move(triangles), depth, part.path};
    child.path.push_back(index);
    return child;
  }

  // The part's two sides (side[i] of part.triangles[i]) as the outcome's
  // parts, each edge-connected piece of a side one part
  void cutInTwo(const layoutMesh &mesh, const triangleAdjacency &adjacency,
                const pendingPart &part, const std::vector<char> &side,
                partOutcome &out)
  {
    std::vector<int> halves[2];
    for(std::size_t i = 0; i < side.size(); i++)
      halves[(int)side[i]].push_back(part.triangles[i]);
    out.split = true;
    out.record.triangles = part.triangles.size();
    out.record.depth = part.depth;
    out.record.reason = out.check.reason;
    for(auto &h : halves)
      for(auto &c : partComponents(adjacency, h, mesh.triangles.size())) {
        const int index = (int)out.parts.size();
        out.parts.push_back(childOf(part, std::move(c), part.depth + 1, index));
        out.record.parts++;
      }
  }

  // One part verified, and cut if refused: first into its edge-connected
  // components, then in two by bisectPart. Each cut leaves strictly smaller
  // parts and the depth is bounded, so the cutting ends. Reads only the
  // mesh and the part (the verifier too): parts go on any thread
  partOutcome processPart(const layoutMesh &mesh,
                          const triangleAdjacency &adjacency,
                          const layoutParameters &parameters,
                          const partVerifier &verify, const pendingPart &part)
  {
    partOutcome out;
    // the part's neighbours, for every step below
    const std::vector<std::array<int, 3> > across =
      partNeighbours(adjacency, part.triangles, mesh.triangles.size());
    std::vector<std::vector<int> > components =
      partComponents(adjacency, part.triangles, mesh.triangles.size(), &across);
    if(components.size() > 1) {
      // not a cut of ours: a patch of Gmsh's classification joined by a
      // node only (or a merge through one)
      for(std::size_t i = 0; i < components.size(); i++)
        out.parts.push_back(
          childOf(part, std::move(components[i]), part.depth, (int)i));
      return out;
    }
    std::vector<char> side =
      separateFansAtPinch(mesh, adjacency, part.triangles, &across);
    if(!side.empty()) {
      // a pinched part fails whatever its map: not mapped
      out.check = {false, "its boundary touches itself at a node", false};
      cutInTwo(mesh, adjacency, part, side, out);
      return out;
    }
    out.check = verify(part.triangles);
    if(out.check.ok || part.triangles.size() < 2 ||
       part.depth >= parameters.maxDepth) {
      out.kept = true;
      return out;
    }
    side = bisectPart(mesh, adjacency, part.triangles,
                      out.check.bySize ? parameters.coarseCutNodes : 0,
                      out.check, &out.record.atFailure, &across);
    out.record.movedFans =
      unpinchCut(mesh, adjacency, part.triangles, side, &across);
    cutInTwo(mesh, adjacency, part, side, out);
    return out;
  }

  // The parts of the stack and all they are cut into, processed by
  // `threads` workers (the calling thread alone for 1): a worker takes the
  // last part pushed, so one feature patch is cut down before the next
  class partWorkers {
  public:
    partWorkers(const layoutMesh &mesh, const triangleAdjacency &adjacency,
                const layoutParameters &parameters, const partVerifier &verify,
                std::vector<pendingPart> stack)
      : _mesh(mesh), _adjacency(adjacency), _parameters(parameters),
        _verify(verify), _stack(std::move(stack))
    {
    }

    void run(int threads)
    {
      std::vector<std::thread> pool;
      for(int i = 1; i < threads; i++) pool.emplace_back([this] { work(); });
      work();
      for(std::thread &t : pool) t.join();
    }

    // (path, triangles, check) of every part kept, and (path, record) of
    // every cut, ordered by path
    std::vector<std::pair<std::vector<int>, partOutcome> > kept, splits;

  private:
    void work()
    {
      std::unique_lock<std::mutex> lock(_mutex);
      while(true) {
        _changed.wait(lock, [this] { return !_stack.empty() || !_busy; });
        if(_stack.empty()) break; // and no worker left to push more
        pendingPart part = std::move(_stack.back());
        _stack.pop_back();
        _busy++;
        lock.unlock();
        partOutcome out =
          processPart(_mesh, _adjacency, _parameters, _verify, part);
        lock.lock();
        for(auto &p : out.parts) _stack.push_back(std::move(p));
        out.parts.clear();
        std::vector<int> path = part.path;
        if(out.kept) {
          out.parts.push_back(std::move(part));
          kept.emplace_back(std::move(path), std::move(out));
        }
        else if(out.split)
          splits.emplace_back(std::move(path), std::move(out));
        _busy--;
        _changed.notify_all();
      }
      _changed.notify_all();
    }

    const layoutMesh &_mesh;
    const triangleAdjacency &_adjacency;
    const layoutParameters &_parameters;
    const partVerifier &_verify;
    std::vector<pendingPart> _stack;
    int _busy = 0;
    std::mutex _mutex;
    std::condition_variable _changed;
  };

  template <class T> void sortByPath(std::vector<T> &v)
  {
    std::sort(v.begin(), v.end(), [](const T &a, const T &b) {
      return std::lexicographical_compare(a.first.begin(), a.first.end(),
                                          b.first.begin(), b.first.end());
    });
  }

  void splitUntilVerified(const layoutMesh &mesh,
                          const triangleAdjacency &adjacency,
                          const layoutParameters &parameters,
                          const partVerifier &verify,
                          std::vector<pendingPart> stack, layoutResult &result)
  {
    partWorkers workers(mesh, adjacency, parameters, verify, std::move(stack));
    workers.run(std::max(1, parameters.threads));
    sortByPath(workers.kept);
    sortByPath(workers.splits);
    for(auto &k : workers.kept) {
      const int index = result.numPatches++;
      for(int t : k.second.parts[0].triangles) result.patch[t] = index;
      if(!k.second.check.ok)
        result.unverified.push_back({index, k.second.check.reason});
    }
    for(auto &s : workers.splits) result.splits.push_back(s.second.record);
  }

} // namespace

layoutResult computePatchLayout(const layoutMesh &mesh,
                                const layoutParameters &parameters,
                                const partVerifier &verify)
{
  layoutResult result;
  result.patch.assign(mesh.triangles.size(), -1);
  if(mesh.triangles.empty()) return result;
  double t0 = wallSeconds();
  triangleAdjacency adjacency = makeTriangleAdjacency(mesh.triangles);
  std::vector<char> feature = featureEdgeFlags(mesh, adjacency);
  result.featuresBelowScale =
    dropFeaturesBelowScale(mesh, adjacency, parameters.featureRadius, feature);
  for(const auto &f : mesh.featureEdges) {
    const int e = adjacency.find(f[0], f[1]);
    if(e < 0 || feature[e]) result.features.push_back(f);
  }
  int numPatches = 0;
  std::vector<int> patch = featurePatches(mesh, adjacency, feature, numPatches);
  result.featurePatches = numPatches;
  result.mergedNoise =
    mergeNoisePatches(mesh, adjacency, parameters, patch, numPatches);
  result.cleanedPatches = numPatches;
  double t1 = wallSeconds();

  std::vector<pendingPart> stack(numPatches);
  for(std::size_t t = 0; t < patch.size(); t++)
    stack[patch[t]].triangles.push_back((int)t);
  for(auto &p : stack) p.depth = 0;
  // the largest last, so that it is verified first (the log reads better,
  // and the longest work starts first); numbered in that order
  std::sort(stack.begin(), stack.end(),
            [](const pendingPart &a, const pendingPart &b) {
              return a.triangles.size() < b.triangles.size();
            });
  for(std::size_t i = 0; i < stack.size(); i++)
    stack[i].path = {(int)(stack.size() - 1 - i)};
  splitUntilVerified(mesh, adjacency, parameters, verify, std::move(stack),
                     result);
  for(std::size_t e = 0; e < adjacency.edges.size(); e++) {
    const int n = adjacency.numTriangles((int)e);
    const int *t = &adjacency.edgeTriangles[adjacency.edgeStart[e]];
    if(n != 2 || result.patch[t[0]] != result.patch[t[1]])
      result.cutEdges.push_back(adjacency.edges[e]);
  }
  result.cleanTime = t1 - t0;
  result.splitTime = wallSeconds() - t1;
  return result;
}
} // namespace reparam
