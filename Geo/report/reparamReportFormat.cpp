// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The report's text: a fixed-width table (one line per face and a total)
// for the log, and the same numbers as JSON for scripts.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include "reparamOptions.h"
#include "reparamReport.h"

namespace reparam {

namespace {

  // Short names for the table's map column
  const char *shortMapName(int map)
  {
    switch(map) {
    case 0: return "Gmsh";
    case 1: return "harmonic";
    case 2: return "Tutte";
    case 3: return "MV";
    case 4: return "LSCM";
    case 5: return "spectral";
    case 7: return "plane";
    }
    return "?";
  }

  // The maps tried, the last one kept: "spectral>LSCM"
  std::string mapColumn(const faceReport &r)
  {
    if(!r.reparametrized) return shortMapName(0);
    std::string s;
    for(int map : r.parametrization.mapsTried)
      s += (s.empty() ? "" : ">") + std::string(shortMapName(map));
    return s;
  }

  void addTimes(const faceReport &r, faceReport &t)
  {
    const parametrizationRecord &p = r.parametrization;
    t.parametrization.patchTime += p.patchTime;
    t.parametrization.fillTime += p.fillTime;
    t.parametrization.assembleTime += p.assembleTime;
    t.parametrization.solveTime += p.solveTime;
    t.parametrization.checkTime += p.checkTime;
    t.parametrization.fallbackTime += p.fallbackTime;
    t.meshTime += r.meshTime;
  }

  void addOptimization(const optimizationRecord &o, optimizationRecord &t)
  {
    if(!o.done) return;
    t.kappaMinBefore =
      t.done ? std::min(t.kappaMinBefore, o.kappaMinBefore) : o.kappaMinBefore;
    t.done = true;
    t.seconds += o.seconds;
    t.inserted += o.inserted;
    t.splits += o.splits;
    t.collapses += o.collapses;
    t.flips += o.flips;
    t.moves += o.moves;
    t.againstBefore += o.againstBefore;
    t.againstAfter += o.againstAfter;
  }

  // The total's quality: extremes over the faces, means weighted by their
  // elements (tau by their edges, geometrically)
  struct qualitySums {
    double kappa = 0., below = 0., eta = 0., tauLog = 0.;
    bool firstTriangles = true, firstQuadrangles = true;

    void add(const faceQuality &q, faceQuality &t)
    {
      if(q.triangles) {
        t.kappaMin = firstTriangles ? q.kappaMin : std::min(t.kappaMin, q.kappaMin);
        firstTriangles = false;
      }
      if(q.quadrangles) {
        t.etaMin = firstQuadrangles ? q.etaMin : std::min(t.etaMin, q.etaMin);
        firstQuadrangles = false;
      }
      t.triangles += q.triangles;
      t.quadrangles += q.quadrangles;
      kappa += q.kappaMean * q.triangles;
      below += q.kappaShareBelow03 * q.triangles;
      eta += q.etaMean * q.quadrangles;
      if(q.edges && q.tau > 0.) {
        tauLog += std::log(q.tau / 100.) * q.edges;
        t.edges += q.edges;
      }
    }

    void finish(faceQuality &t) const
    {
      if(t.triangles) {
        t.kappaMean = kappa / t.triangles;
        t.kappaShareBelow03 = below / t.triangles;
      }
      if(t.quadrangles) t.etaMean = eta / t.quadrangles;
      if(t.edges) t.tau = 100. * std::exp(tauLog / t.edges);
    }
  };

  // The total's distances: the largest of the faces', the mean weighted by
  // their elements, or `whole`'s (the faces against their inputs together)
  struct fidelitySums {
    double meanDistance = 0., hausdorff = 0.;
    std::size_t sampled = 0;

    void add(const faceReport &r, faceReport &t)
    {
      if(!r.hasInput) return;
      t.hasInput = true;
      t.inputBox += r.inputBox;
      if(r.fidelity.hausdorff >= hausdorff) {
        hausdorff = r.fidelity.hausdorff;
        t.fidelity.farthest = r.fidelity.farthest;
        t.fidelity.farthestOnInput = r.fidelity.farthestOnInput;
      }
      meanDistance += r.fidelity.meanDistance * r.fidelity.elements;
      sampled += r.fidelity.elements;
      t.fidelity.elements += r.fidelity.elements;
      t.fidelity.inverted += r.fidelity.inverted;
    }

    void finish(const meshFidelity *whole, faceReport &t) const
    {
      if(!t.hasInput) return;
      t.fidelity.hausdorff = hausdorff;
      t.fidelity.meanDistance = sampled ? meanDistance / sampled : 0.;
      t.fidelity.diagonal = t.inputBox.empty() ? 0. : t.inputBox.diag();
      if(whole) {
        t.fidelity.hausdorff = whole->hausdorff;
        t.fidelity.meanDistance = whole->meanDistance;
        t.fidelity.farthest = whole->farthest;
        t.fidelity.farthestOnInput = whole->farthestOnInput;
      }
    }
  };

  // The sums and extremes of the total line, in the same struct as a face
  faceReport total(const std::vector<faceReport> &reports,
                   const meshFidelity *whole)
  {
    faceReport t;
    qualitySums quality;
    fidelitySums fidelity;
    for(const faceReport &r : reports) {
      addTimes(r, t);
      for(int c = 0; c < numPoorTriangleCauses; c++)
        t.poorTriangles[c] += r.poorTriangles[c];
      addOptimization(r.optimization, t.optimization);
      quality.add(r.quality, t.quality);
      fidelity.add(r, t);
    }
    quality.finish(t.quality);
    fidelity.finish(whole, t);
    return t;
  }

  double percentOfDiagonal(double distance, double diagonal)
  {
    return diagonal > 0. ? 100. * distance / diagonal : 0.;
  }

  std::string tableLine(const std::string &surface, const std::string &map,
                        const faceReport &r)
  {
    const parametrizationRecord &p = r.parametrization;
    const faceQuality &q = r.quality;
    char eta[32] = "     -      -", fidelity[48] = "       -        -        -";
    if(q.quadrangles)
      snprintf(eta, sizeof(eta), "%6.3f %6.3f", q.etaMin, q.etaMean);
    if(r.hasInput)
      snprintf(fidelity, sizeof(fidelity), "%8.3g %8.3g %8lu",
               percentOfDiagonal(r.fidelity.hausdorff, r.fidelity.diagonal),
               percentOfDiagonal(r.fidelity.meanDistance, r.fidelity.diagonal),
               r.fidelity.inverted);
    char line[512];
    snprintf(line, sizeof(line),
             "%-9s %-16s %6.3f %6.3f %6.3f %6.3f %6.3f %6.3f %7.3f %9lu %7lu "
             "%6.3f %6.3f %5.1f %s %5.1f %s",
             surface.c_str(), map.c_str(), p.patchTime, p.fillTime,
             p.assembleTime, p.solveTime, p.fallbackTime, p.checkTime,
             r.meshTime, q.triangles, q.quadrangles, q.kappaMin, q.kappaMean,
             100. * q.kappaShareBelow03, eta, q.tau, fidelity);
    return line;
  }

  // JSON has no NaN nor infinity
  std::string number(double x)
  {
    if(!std::isfinite(x)) return "null";
    char s[32];
    snprintf(s, sizeof(s), "%.6g", x);
    return s;
  }

  std::string jsonFields(const faceReport &r)
  {
    const parametrizationRecord &p = r.parametrization;
    const faceQuality &q = r.quality;
    std::string s;
    s += "\"seconds\": {\"patch\": " + number(p.patchTime) +
         ", \"fill\": " + number(p.fillTime) +
         ", \"assemble\": " + number(p.assembleTime) +
         ", \"solve\": " + number(p.solveTime) +
         ", \"fallbackMaps\": " + number(p.fallbackTime) +
         ", \"checks\": " + number(p.checkTime) +
         ", \"planarMesh\": " + number(r.meshTime) + "}";
    s += ", \"triangles\": " + std::to_string(q.triangles);
    s += ", \"quadrangles\": " + std::to_string(q.quadrangles);
    s += ", \"kappaMin\": " + number(q.triangles ? q.kappaMin : NAN);
    s += ", \"kappaMean\": " + number(q.triangles ? q.kappaMean : NAN);
    s += ", \"kappaShareBelow03\": " +
         number(q.triangles ? q.kappaShareBelow03 : NAN);
    s += ", \"etaMin\": " + number(q.quadrangles ? q.etaMin : NAN);
    s += ", \"etaMean\": " + number(q.quadrangles ? q.etaMean : NAN);
    s += ", \"tau\": " + number(q.edges ? q.tau : NAN);
    s += ", \"hausdorffPercent\": " +
         number(r.hasInput ?
                  percentOfDiagonal(r.fidelity.hausdorff, r.fidelity.diagonal) :
                  NAN);
    s += ", \"meanDistancePercent\": " +
         number(r.hasInput ? percentOfDiagonal(r.fidelity.meanDistance,
                                               r.fidelity.diagonal) :
                             NAN);
    s += ", \"diagonal\": " + number(r.hasInput ? r.fidelity.diagonal : NAN);
    if(r.hasInput) {
      const SPoint3 &p = r.fidelity.farthest;
      s += ", \"hausdorffAt\": [" + number(p.x()) + ", " + number(p.y()) +
           ", " + number(p.z()) + "], \"hausdorffFrom\": \"" +
           (r.fidelity.farthestOnInput ? "input" : "mesh") + "\"";
    }
    s += ", \"inverted\": " +
         (r.hasInput ? std::to_string(r.fidelity.inverted) : "null");
    // the causes of the triangles below kappa 0.3
    const char *causes[numPoorTriangleCauses] = {
      "sharpCurveAngle", "shortCurveSegment", "narrowStrip", "inside"};
    s += ", \"poorTriangleCauses\": {";
    for(int c = 0; c < numPoorTriangleCauses; c++)
      s += std::string(c ? ", \"" : "\"") + causes[c] +
           "\": " + std::to_string(r.poorTriangles[c]);
    s += "}";
    const optimizationRecord &o = r.optimization;
    if(o.done)
      s += ", \"optimization\": {\"kappaMinBefore\": " +
           number(o.kappaMinBefore) + ", \"seconds\": " + number(o.seconds) +
           ", \"insertedInputNodes\": " + std::to_string(o.inserted) +
           ", \"longEdgeSplits\": " + std::to_string(o.splits) +
           ", \"shortEdgeCollapses\": " + std::to_string(o.collapses) +
           ", \"flips\": " + std::to_string(o.flips) +
           ", \"moves\": " + std::to_string(o.moves) +
           ", \"againstInputBefore\": " + std::to_string(o.againstBefore) +
           ", \"againstInputAfter\": " + std::to_string(o.againstAfter) + "}";
    else
      s += ", \"optimization\": null";
    return s;
  }

} // namespace

std::vector<std::string> reportTable(const std::vector<faceReport> &reports,
                                     const meshFidelity *whole)
{
  std::vector<std::string> lines;
  char header[512];
  snprintf(header, sizeof(header),
           "%-9s %-16s %6s %6s %6s %6s %6s %6s %7s %9s %7s %6s %6s %5s %6s "
           "%6s "
           "%5s %8s %8s %8s",
           "surface", "map (tried)", "patch", "fill", "assem.", "solve",
           "fallbk", "checks", "mesh", "triangles", "quads", "k min", "k mean",
           "k<0.3", "e min", "e mean", "tau", "Hausd.%", "mean d.%",
           "inverted");
  lines.push_back(header);
  for(const faceReport &r : reports)
    lines.push_back(tableLine(std::to_string(r.tag), mapColumn(r), r));
  char surfaces[32];
  snprintf(surfaces, sizeof(surfaces), "%lu surf.", reports.size());
  lines.push_back(tableLine("total", surfaces, total(reports, whole)));
  return lines;
}

std::string poorTrianglesLine(const std::vector<faceReport> &reports)
{
  const faceReport t = total(reports, nullptr);
  std::size_t all = 0;
  for(std::size_t n : t.poorTriangles) all += n;
  if(!all) return "";
  std::string line = std::to_string(all) + " triangle" + (all > 1 ? "s" : "") +
                     " below kappa 0.3:";
  bool first = true;
  for(int c = 0; c < numPoorTriangleCauses; c++) {
    if(!t.poorTriangles[c]) continue;
    line += std::string(first ? " " : ", ") +
            std::to_string(t.poorTriangles[c]) + " " +
            poorTriangleCauseName((poorTriangleCause)c);
    first = false;
  }
  return line;
}

std::string narrowFacesLine(const std::vector<faceReport> &reports,
                            const std::set<int> &narrow)
{
  std::size_t inside = 0, outside = 0, faces = 0;
  double kappaInside = 0., kappaOutside = 0.;
  std::string tags;
  for(const faceReport &r : reports) {
    const faceQuality &q = r.quality;
    if(!q.triangles) continue;
    if(!narrow.count(r.tag)) {
      outside += q.triangles;
      kappaOutside += q.kappaMean * q.triangles;
      continue;
    }
    inside += q.triangles;
    kappaInside += q.kappaMean * q.triangles;
    if(faces++ < 8)
      tags += (tags.empty() ? "" : ", ") + std::to_string(r.tag);
    else if(faces == 9)
      tags += ", ...";
  }
  if(!inside || !outside) return "";
  char line[512];
  snprintf(line, sizeof(line),
           "kappa mean %.3g: %.3g on the %lu surface%s narrower than a "
           "quarter of the size asked (%s; %lu triangles), %.3g on "
           "the others",
           (kappaInside + kappaOutside) / (inside + outside),
           kappaInside / inside, faces, faces > 1 ? "s" : "", tags.c_str(),
           inside,
           kappaOutside / outside);
  return line;
}

std::string optimizationLine(const std::vector<faceReport> &reports)
{
  const faceReport t = total(reports, nullptr);
  const optimizationRecord &o = t.optimization;
  if(!o.done) return "";
  char line[320];
  snprintf(line, sizeof(line),
           "optimization on the input (Mesh.CompoundOptimize): kappa min "
           "%.3g -> %.3g, %lu input nodes the mesh cut off inserted, %lu long "
           "edges split, %lu short ones collapsed, %lu flips, %lu node moves, "
           "%lu -> %lu triangles against the input, in %g s",
           o.kappaMinBefore, t.quality.kappaMin, o.inserted, o.splits,
           o.collapses, o.flips,
           o.moves, o.againstBefore, o.againstAfter, o.seconds);
  return line;
}

std::string farthestPointLine(const std::vector<faceReport> &reports,
                              const meshFidelity *whole)
{
  const faceReport t = total(reports, whole);
  if(!t.hasInput) return "";
  const meshFidelity &f = t.fidelity;
  char line[256];
  snprintf(line, sizeof(line),
           "largest distance to the input %g (%.3g %% of the diagonal) at "
           "(%g, %g, %g): %s",
           f.hausdorff, percentOfDiagonal(f.hausdorff, f.diagonal),
           f.farthest.x(), f.farthest.y(), f.farthest.z(),
           f.farthestOnInput ? "an input point far from the mesh" :
                               "a mesh point far from the input");
  return line;
}

std::string reportJson(const std::vector<faceReport> &reports,
                       const std::vector<int> &unmeshed,
                       const meshFidelity *whole,
                       const std::vector<int> &keptAsInput,
                       const std::set<int> &narrow)
{
  std::string s = "{\n  \"parametrizationOption\": " +
                  std::to_string(getReparamOptions().parametrization) +
                  ",\n  \"surfaces\": [";
  for(std::size_t i = 0; i < reports.size(); i++) {
    const faceReport &r = reports[i];
    const parametrizationRecord &p = r.parametrization;
    s += i ? ",\n    {" : "\n    {";
    s += "\"surface\": " + std::to_string(r.tag);
    s +=
      ", \"map\": \"" +
      std::string(compoundParametrizationName(r.reparametrized ? p.map : 0)) +
      "\", \"mapsTried\": [";
    for(std::size_t j = 0; j < p.mapsTried.size(); j++)
      s += (j ? ", \"" : "\"") +
           std::string(compoundParametrizationName(p.mapsTried[j])) + "\"";
    s += "], \"oneToOne\": " + std::string(!r.reparametrized ? "null" :
                                           p.bijective       ? "true" :
                                                               "false");
    s += ", \"nodes\": " + std::to_string(p.nodes);
    s += ", \"inputTriangles\": " + std::to_string(p.triangles);
    s += ", \"holes\": " + std::to_string(p.holes);
    s += ", \"filledHoles\": " + std::to_string(p.filledHoles) + ", ";
    s += jsonFields(r) + "}";
  }
  s += "\n  ],\n  \"unmeshedSurfaces\": [";
  for(std::size_t i = 0; i < unmeshed.size(); i++)
    s += (i ? ", " : "") + std::to_string(unmeshed[i]);
  s += "],\n  \"inputKeptSurfaces\": [";
  for(std::size_t i = 0; i < keptAsInput.size(); i++)
    s += (i ? ", " : "") + std::to_string(keptAsInput[i]);
  s += "],\n  \"narrowSurfaces\": [";
  std::size_t listed = 0;
  for(int tag : narrow) s += (listed++ ? ", " : "") + std::to_string(tag);
  s += "],\n  \"total\": {\"surfaces\": " + std::to_string(reports.size()) +
       ", " + jsonFields(total(reports, whole)) + "}\n}\n";
  return s;
}
} // namespace reparam

