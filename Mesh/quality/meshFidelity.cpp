// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "SBoundingBox3d.h"
#include "SVector3.h"
#include "closestTriangle.h"
#include "meshFidelity.h"

namespace reparam {

namespace {

  SVector3 triangleNormal(const surfaceMesh &m, const std::array<int, 3> &t)
  {
    return crossprod(SVector3(m.points[t[0]], m.points[t[1]]),
                     SVector3(m.points[t[0]], m.points[t[2]]));
  }

  // the cross product of the diagonals: twice the area vector of the quad
  SVector3 quadrangleNormal(const surfaceMesh &m, const std::array<int, 4> &q)
  {
    return crossprod(SVector3(m.points[q[0]], m.points[q[2]]),
                     SVector3(m.points[q[1]], m.points[q[3]]));
  }

  template <int N>
  SPoint3 centroid(const surfaceMesh &m, const std::array<int, N> &e)
  {
    SPoint3 g(0., 0., 0.);
    for(int j : e) g += m.points[j];
    return g * (1. / N);
  }

  // Whether an element (its corners) points against the input under it:
  // the sum of the unit normals of the input triangles closest to its
  // centroid and to the points halfway to its corners. One sample alone
  // would call inverted a coarse element laid across a ridge of the input
  // (its normal is then nearly tangent to the input on either side).
  template <int N>
  bool cornersAgainst(const std::array<SPoint3, N> &corners,
                      const SVector3 &normal, const surfaceMesh &input,
                      const closestTriangleSearch &onInput,
                      const closestTriangleHit &atCentroid)
  {
    auto unitNormal = [&](int t) {
      SVector3 n = triangleNormal(input, input.triangles[t]);
      double l = n.norm();
      return l > 0. ? n * (1. / l) : n;
    };
    SPoint3 g(0., 0., 0.);
    for(const SPoint3 &p : corners) g += p;
    g *= 1. / N;
    SVector3 sum = unitNormal(atCentroid.triangle);
    // each sample left adds at least -|normal| to the product: once the
    // samples so far outweigh them all (with a margin far above round-off),
    // the answer is known and their searches are spared (a quarter of the
    // optimizer's, which asks this of every change it tries)
    const double bound = normal.norm() * (1. + 1e-9);
    for(int j = 0; j < N; j++) {
      const double partial = dot(normal, sum), left = (N - j) * bound;
      if(partial > left) return false;
      if(partial < -left) return true;
      SPoint3 half = (g + corners[j]) * 0.5;
      sum += unitNormal(onInput.closest(half, atCentroid.triangle).triangle);
    }
    return dot(normal, sum) < 0.;
  }

  template <int N>
  bool pointsAgainst(const surfaceMesh &m, const std::array<int, N> &e,
                     const SVector3 &normal, const surfaceMesh &input,
                     const closestTriangleSearch &onInput,
                     const closestTriangleHit &atCentroid)
  {
    std::array<SPoint3, N> corners;
    for(int j = 0; j < N; j++) corners[j] = m.points[e[j]];
    return cornersAgainst<N>(corners, normal, input, onInput, atCentroid);
  }

  struct oneSided {
    double max = 0., sum = 0.;
    SPoint3 at;
    std::size_t samples = 0;
    void add(double d, const SPoint3 &p)
    {
      if(d > max || !samples) {
        max = d;
        at = p;
      }
      sum += d;
      samples++;
    }
  };

  SVector3 elementNormal(const surfaceMesh &m, const std::array<int, 3> &t)
  {
    return triangleNormal(m, t);
  }
  SVector3 elementNormal(const surfaceMesh &m, const std::array<int, 4> &q)
  {
    return quadrangleNormal(m, q);
  }

  // The distances from the centroids of `elements` of `from` to `to` into
  // `s`, the elements against `to` counted into `inverted` when given
  template <int N>
  void centroidDistances(const surfaceMesh &from,
                         const std::vector<std::array<int, N> > &elements,
                         const surfaceMesh &to,
                         const closestTriangleSearch &search, int &last,
                         oneSided &s, std::size_t *inverted)
  {
    for(const auto &e : elements) {
      const SPoint3 g = centroid<N>(from, e);
      closestTriangleHit hit = search.closest(g, last);
      last = hit.triangle;
      s.add(hit.distance, g);
      if(inverted)
        *inverted +=
          pointsAgainst<N>(from, e, elementNormal(from, e), to, search, hit);
    }
  }

  // distances from the nodes and element centroids of `from` to `to`, and
  // the elements of `from` whose normal points against the closest triangle
  // of `to` (normals: of the triangles of `to`)
  oneSided distances(const surfaceMesh &from, const surfaceMesh &to,
                     const closestTriangleSearch &search,
                     std::size_t *inverted = nullptr)
  {
    oneSided s;
    // each search starts from the triangle the one before found: meshes
    // number their nodes and elements by neighbourhoods
    int last = -1;
    for(const SPoint3 &p : from.points) {
      const closestTriangleHit hit = search.closest(p, last);
      s.add(hit.distance, p);
      last = hit.triangle;
    }
    centroidDistances<3>(from, from.triangles, to, search, last, s, inverted);
    centroidDistances<4>(from, from.quadrangles, to, search, last, s,
                         inverted);
    return s;
  }

} // namespace

bool triangleAgainstInput(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c,
                          const surfaceMesh &input,
                          const closestTriangleSearch &onInput)
{
  return triangleAgainstInput(a, b, c, input, onInput,
                              onInput.closest((a + b + c) * (1. / 3.)));
}

bool triangleAgainstInput(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c,
                          const surfaceMesh &input,
                          const closestTriangleSearch &onInput,
                          const closestTriangleHit &atCentroid)
{
  // no surfaceMesh made: the optimizer asks this for every change it tries
  return cornersAgainst<3>({{a, b, c}},
                           crossprod(SVector3(a, b), SVector3(a, c)), input,
                           onInput, atCentroid);
}

bool quadrangleAgainstInput(const SPoint3 &a, const SPoint3 &b,
                            const SPoint3 &c, const SPoint3 &d,
                            const surfaceMesh &input,
                            const closestTriangleSearch &onInput)
{
  return cornersAgainst<4>({{a, b, c, d}},
                           crossprod(SVector3(a, c), SVector3(b, d)), input,
                           onInput, onInput.closest((a + b + c + d) * 0.25));
}

namespace {

  // Hausdorff: the largest of both sides; mean: the mean of both means
  void combine(const oneSided &there, const oneSided &back, meshFidelity &f)
  {
    f.hausdorff = std::max(there.max, back.max);
    f.farthestOnInput = back.max > there.max;
    f.farthest = f.farthestOnInput ? back.at : there.at;
    f.meanDistance =
      0.5 * (there.sum / std::max<std::size_t>(1, there.samples) +
             back.sum / std::max<std::size_t>(1, back.samples));
  }

  // distances() with each sample counted for its part too
  oneSided distancesByPart(const surfaceMesh &from,
                           const std::vector<int> &pointPart,
                           const std::vector<int> &elementPart,
                           const closestTriangleSearch &search,
                           std::vector<oneSided> &parts)
  {
    oneSided s;
    // each search starts from the triangle the one before found (as in
    // distances()): the same exact distances, fewer boxes opened
    int last = -1;
    for(std::size_t i = 0; i < from.points.size(); i++) {
      const closestTriangleHit hit = search.closest(from.points[i], last);
      last = hit.triangle;
      s.add(hit.distance, from.points[i]);
      parts[pointPart[i]].add(hit.distance, from.points[i]);
    }
    for(std::size_t i = 0; i < from.triangles.size(); i++) {
      const SPoint3 g = centroid<3>(from, from.triangles[i]);
      const closestTriangleHit hit = search.closest(g, last);
      last = hit.triangle;
      s.add(hit.distance, g);
      parts[elementPart[i]].add(hit.distance, g);
    }
    return s;
  }

} // namespace

meshFidelity compareDistancesToInput(const std::vector<surfaceMesh> &inputs,
                                     const std::vector<surfaceMesh> &outputs,
                                     std::vector<meshFidelity> *perMesh)
{
  meshFidelity f;
  std::vector<int> inputPoint, inputElement, outputPoint, outputElement;
  surfaceMesh input = unionAsTriangles(inputs, &inputPoint, &inputElement);
  surfaceMesh output = unionAsTriangles(outputs, &outputPoint, &outputElement);
  f.elements = output.triangles.size();
  SBoundingBox3d box;
  for(const SPoint3 &p : input.points) box += p;
  if(!input.points.empty()) f.diagonal = box.diag();
  if(perMesh) {
    perMesh->assign(outputs.size(), meshFidelity());
    for(std::size_t i = 0; i < outputs.size() && i < inputs.size(); i++) {
      SBoundingBox3d own;
      for(const SPoint3 &p : inputs[i].points) own += p;
      (*perMesh)[i].elements = outputs[i].numElements();
      if(!inputs[i].points.empty()) (*perMesh)[i].diagonal = own.diag();
    }
  }
  if(input.triangles.empty() || output.triangles.empty()) return f;
  closestTriangleSearch onInput(input.points, input.triangles);
  closestTriangleSearch onOutput(output.points, output.triangles);
  std::vector<oneSided> there(outputs.size()), back(inputs.size());
  combine(distancesByPart(output, outputPoint, outputElement, onInput, there),
          distancesByPart(input, inputPoint, inputElement, onOutput, back), f);
  if(perMesh)
    for(std::size_t i = 0; i < perMesh->size() && i < back.size(); i++)
      combine(there[i], back[i], (*perMesh)[i]);
  return f;
}

meshFidelity compareToInput(const surfaceMesh &input, const surfaceMesh &output,
                            const std::size_t *knownInverted)
{
  meshFidelity f;
  f.elements = output.numElements();
  SBoundingBox3d box;
  for(const SPoint3 &p : input.points) box += p;
  if(!input.points.empty()) f.diagonal = box.diag();
  if(input.triangles.empty() || !f.elements) return f;

  closestTriangleSearch onInput(input.points, input.triangles);
  oneSided there =
    distances(output, input, onInput, knownInverted ? nullptr : &f.inverted);
  if(knownInverted) f.inverted = *knownInverted;
  // the output as triangles for the search from the input side
  std::vector<std::array<int, 3> > outputTriangles = output.triangles;
  for(const auto &q : output.quadrangles) {
    outputTriangles.push_back({{q[0], q[1], q[2]}});
    outputTriangles.push_back({{q[0], q[2], q[3]}});
  }
  surfaceMesh outputAsTriangles;
  outputAsTriangles.points = output.points;
  outputAsTriangles.triangles = std::move(outputTriangles);
  closestTriangleSearch onOutput(outputAsTriangles.points,
                                 outputAsTriangles.triangles);
  combine(there, distances(input, outputAsTriangles, onOutput), f);
  return f;
}

std::vector<std::size_t> invertedElements(const surfaceMesh &input,
                                          const surfaceMesh &output)
{
  std::vector<std::size_t> inverted;
  if(input.triangles.empty()) return inverted;
  closestTriangleSearch onInput(input.points, input.triangles);
  for(std::size_t i = 0; i < output.triangles.size(); i++) {
    const auto &t = output.triangles[i];
    if(pointsAgainst<3>(output, t, triangleNormal(output, t), input, onInput,
                        onInput.closest(centroid<3>(output, t))))
      inverted.push_back(i);
  }
  for(std::size_t i = 0; i < output.quadrangles.size(); i++) {
    const auto &q = output.quadrangles[i];
    if(pointsAgainst<4>(output, q, quadrangleNormal(output, q), input, onInput,
                        onInput.closest(centroid<4>(output, q))))
      inverted.push_back(output.triangles.size() + i);
  }
  return inverted;
}

std::size_t countInverted(const surfaceMesh &input, const surfaceMesh &output)
{
  return invertedElements(input, output).size();
}

surfaceMesh unionAsTriangles(const std::vector<surfaceMesh> &meshes,
                             std::vector<int> *pointPart,
                             std::vector<int> *elementPart)
{
  surfaceMesh u;
  for(std::size_t i = 0; i < meshes.size(); i++) {
    const surfaceMesh &m = meshes[i];
    const int offset = (int)u.points.size();
    u.points.insert(u.points.end(), m.points.begin(), m.points.end());
    for(const auto &t : m.triangles)
      u.triangles.push_back({{t[0] + offset, t[1] + offset, t[2] + offset}});
    for(const auto &q : m.quadrangles) {
      u.triangles.push_back({{q[0] + offset, q[1] + offset, q[2] + offset}});
      u.triangles.push_back({{q[0] + offset, q[2] + offset, q[3] + offset}});
    }
    if(pointPart) pointPart->resize(u.points.size(), (int)i);
    if(elementPart) elementPart->resize(u.triangles.size(), (int)i);
  }
  return u;
}
} // namespace reparam

