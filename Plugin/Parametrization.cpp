// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "GFace.h"
#include "GModel.h"
#include "PView.h"
#include "PViewOptions.h"
#include "Parametrization.h"
#include "reparamPluginRegistration.h"
#include "mapDistortion.h"
#include "reparamOptions.h"
#include "reparamReport.h"
#include "reparamViews.h"

using namespace reparam;

StringXNumber ParametrizationOptions_Number[] = {
  {GMSH_FULLRC, "SurfaceTag", nullptr, -1.},
  {GMSH_FULLRC, "IsoLines", nullptr, 20.}};

static const bool parametrizationRegistered =
  registerReparamPlugin<GMSH_ParametrizationPlugin>("Parametrization");

std::string GMSH_ParametrizationPlugin::getHelp() const
{
  return "Plugin(Parametrization) shows the parametrization of the discrete "
         "(and compound) surface `SurfaceTag' (of all surfaces that have one "
         "if "
         "`SurfaceTag' < 0), i.e. the (u, v) of the nodes of the triangulation "
         "it was computed on, with the map chosen by "
         "Mesh.CompoundParametrization, once CreateGeometry (or meshing a "
         "compound) has run.\n\n"
         "Plugin(Parametrization) creates five views: `u' and `v' on the 3D "
         "triangulation (drawn as `IsoLines' iso-lines), `flattened' (the "
         "triangulation in the (u, v) plane, the first surface where it is, "
         "the next ones side by side to its right, "
         "valued by their tag), `angle distortion' (the ratio of the "
         "singular values of each triangle's map: 1 if conformal, 0 marks "
         "a flipped triangle) and `area distortion' (the share of the (u, v) "
         "area of each triangle over its share of the 3D area: 1 if area "
         "preserving, negative if flipped).";
}

int GMSH_ParametrizationPlugin::getNbOptions() const
{
  return sizeof(ParametrizationOptions_Number) / sizeof(StringXNumber);
}

StringXNumber *GMSH_ParametrizationPlugin::getOption(int iopt)
{
  return &ParametrizationOptions_Number[iopt];
}

namespace {

  // The per-node and per-triangle fields of all the surfaces shown
  struct parametrizationFields {
    surfaceMesh surface, flattened;
    std::vector<double> u, v, tag; // per node
    std::vector<double> angle, area; // per triangle
  };

  double triangleArea(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c)
  {
    SVector3 n = crossprod(SVector3(a, b), SVector3(a, c));
    return 0.5 * n.norm();
  }

  double signedUvArea(const SPoint2 &a, const SPoint2 &b, const SPoint2 &c)
  {
    return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) -
                  (c.x() - a.x()) * (b.y() - a.y()));
  }

  // Appends face gf, its flattened copy shifted by `shift` along u
  void appendFace(const GFace *gf, double shift, parametrizationFields &f)
  {
    const std::vector<SPoint3> &xyz = gf->stl_vertices_xyz;
    const std::vector<SPoint2> &uv = gf->stl_vertices_uv;
    const std::vector<int> &tri = gf->stl_triangles;
    const int offset = (int)f.surface.points.size();
    for(std::size_t i = 0; i < xyz.size(); i++) {
      f.surface.points.push_back(xyz[i]);
      f.flattened.points.push_back(SPoint3(uv[i].x() + shift, uv[i].y(), 0.));
      f.u.push_back(uv[i].x());
      f.v.push_back(uv[i].y());
      f.tag.push_back(gf->tag());
    }
    double area3d = 0., areaUv = 0.;
    for(std::size_t t = 0; t + 2 < tri.size(); t += 3) {
      area3d += triangleArea(xyz[tri[t]], xyz[tri[t + 1]], xyz[tri[t + 2]]);
      areaUv += signedUvArea(uv[tri[t]], uv[tri[t + 1]], uv[tri[t + 2]]);
    }
    // a mirrored map (negative total) is still one-to-one: compare shares
    const double sign = areaUv < 0. ? -1. : 1.;
    for(std::size_t t = 0; t + 2 < tri.size(); t += 3) {
      const int a = tri[t], b = tri[t + 1], c = tri[t + 2];
      f.surface.triangles.push_back({offset + a, offset + b, offset + c});
      double uva[2] = {uv[a].x(), sign * uv[a].y()};
      double uvb[2] = {uv[b].x(), sign * uv[b].y()};
      double uvc[2] = {uv[c].x(), sign * uv[c].y()};
      double angle = angleDistortion(xyz[a], xyz[b], xyz[c], uva, uvb, uvc);
      f.angle.push_back(std::isfinite(angle) ? angle : 0.);
      double share3d = triangleArea(xyz[a], xyz[b], xyz[c]) / area3d;
      double shareUv = sign * signedUvArea(uv[a], uv[b], uv[c]) / areaUv;
      f.area.push_back(share3d > 0. ? shareUv / share3d : 0.);
    }
    f.flattened.triangles.insert(f.flattened.triangles.end(),
                                 f.surface.triangles.end() - tri.size() / 3,
                                 f.surface.triangles.end());
  }

} // namespace

PView *GMSH_ParametrizationPlugin::execute(PView *view)
{
  const int tag = (int)ParametrizationOptions_Number[0].def;
  const int isoLines = std::max(1, (int)ParametrizationOptions_Number[1].def);

  std::vector<GFace *> faces;
  GModel *m = GModel::current();
  for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
    GFace *gf = *it;
    if(tag >= 0 && gf->tag() != tag) continue;
    if(gf->stl_triangles.empty() ||
       gf->stl_vertices_uv.size() != gf->stl_vertices_xyz.size())
      continue;
    faces.push_back(gf);
  }
  if(faces.empty()) {
    Msg::Warning("Parametrization: %s has no parametrization (run "
                 "CreateGeometry on a classified mesh, or mesh a compound, "
                 "first)",
                 tag < 0 ? "no surface" :
                           ("surface " + std::to_string(tag)).c_str());
    return view;
  }

  parametrizationFields f;
  double right = 0.; // of the flattened faces so far, with a gap
  for(GFace *gf : faces) {
    double umin = 0., umax = 0.;
    for(std::size_t i = 0; i < gf->stl_vertices_uv.size(); i++) {
      double u = gf->stl_vertices_uv[i].x();
      umin = i ? std::min(umin, u) : u;
      umax = i ? std::max(umax, u) : u;
    }
    const std::size_t first = f.angle.size();
    // the first face where it is, the next ones to its right
    const double shift = first ? right - umin : 0.;
    appendFace(gf, shift, f);
    right = umax + shift + 0.1 * (umax - umin);

    double angleSum = 0., angleMax = 0., areaMin = 0., areaMax = 0.;
    std::size_t flipped = 0, counted = 0;
    for(std::size_t t = first; t < f.angle.size(); t++) {
      areaMin = t > first ? std::min(areaMin, f.area[t]) : f.area[t];
      areaMax = t > first ? std::max(areaMax, f.area[t]) : f.area[t];
      if(f.angle[t] == 0.) {
        flipped++;
        continue;
      }
      angleSum += f.angle[t];
      angleMax = std::max(angleMax, f.angle[t]);
      counted++;
    }
    const parametrizationRecord *p = findParametrization(gf);
    Msg::Info("Parametrization: surface %d (%s map): %lu triangles, angle "
              "distortion mean %.4g max %.4g, area distortion %.3g to %.3g, "
              "%lu flipped",
              gf->tag(), compoundParametrizationName(p ? p->map : 0),
              f.angle.size() - first, counted ? angleSum / counted : 0.,
              angleMax, areaMin, areaMax, flipped);
  }

  for(const char *name : {"u", "v"}) {
    PView *iso = nodalValueView(name, f.surface, name[0] == 'u' ? f.u : f.v);
    iso->getOptions()->intervalsType = PViewOptions::Iso;
    iso->getOptions()->nbIso = isoLines;
  }
  PView *flat = nodalValueView("flattened", f.flattened, f.tag);
  flat->getOptions()->showElement = 1;
  elementValueView("angle distortion", f.surface, f.angle);
  return elementValueView("area distortion", f.surface, f.area);
}
