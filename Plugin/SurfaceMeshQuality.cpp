// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "GFace.h"
#include "GModel.h"
#include "OpenFile.h"
#include "reparamPluginRegistration.h"
#include "SurfaceMeshQuality.h"
#include "faceQuality.h"
#include "meshFidelity.h"
#include "quadQuality.h"
#include "reparamSurfaceMesh.h"
#include "reparamViews.h"
#include "triangleQuality.h"

using namespace reparam;

StringXNumber SurfaceMeshQualityOptions_Number[] = {
  {GMSH_FULLRC, "SurfaceTag", nullptr, -1.},
  {GMSH_FULLRC, "CreateViews", nullptr, 1.},
  {GMSH_FULLRC, "HistogramBins", nullptr, 20.}};

StringXString SurfaceMeshQualityOptions_String[] = {
  {GMSH_FULLRC, "Reference", nullptr, ""}};

static const bool surfaceMeshQualityRegistered =
  registerReparamPlugin<GMSH_SurfaceMeshQualityPlugin>("SurfaceMeshQuality");

std::string GMSH_SurfaceMeshQualityPlugin::getHelp() const
{
  return "Plugin(SurfaceMeshQuality) measures the mesh of surface `SurfaceTag' "
         "(of all surfaces if `SurfaceTag' < 0), whatever made it: the aspect "
         "ratio kappa = 4 sin a sin b sin c / (sin a + sin b + sin c) of the "
         "triangles (minimum, mean, share below 0.3), the quality eta of the "
         "quadrangles (1 for a square, 0 with a flat or reflex corner), the "
         "efficiency index tau of the edges in the mesh size field (100% "
         "when every edge has the prescribed size) and, for discrete "
         "surfaces, the Hausdorff and mean distances to the triangulation "
         "they were parametrized from (in % of its bounding box diagonal) "
         "and the elements pointing against it.\n\n"
         "If `Reference' names a mesh file (an STL, or any mesh Gmsh "
         "merges), the measured surfaces are also compared with its "
         "triangles as one: the Hausdorff and mean distances (in % of its "
         "bounding box diagonal) and the elements pointing against it, "
         "whatever made the mesh (another remesher's output merged as an "
         "STL, against the STL it remeshed). The elements are tested "
         "against the reference as a whole: across a wall thinner than "
         "them its other side may be the closest, and count.\n\n"
         "If `CreateViews' is set, Plugin(SurfaceMeshQuality) creates a view "
         "of kappa per triangle, one of eta per quadrangle (if any) and "
         "their histograms over `HistogramBins' bins of [0, 1].";
}

int GMSH_SurfaceMeshQualityPlugin::getNbOptions() const
{
  return sizeof(SurfaceMeshQualityOptions_Number) / sizeof(StringXNumber);
}

StringXNumber *GMSH_SurfaceMeshQualityPlugin::getOption(int iopt)
{
  return &SurfaceMeshQualityOptions_Number[iopt];
}

int GMSH_SurfaceMeshQualityPlugin::getNbOptionsStr() const
{
  return sizeof(SurfaceMeshQualityOptions_String) / sizeof(StringXString);
}

StringXString *GMSH_SurfaceMeshQualityPlugin::getOptionStr(int iopt)
{
  return &SurfaceMeshQualityOptions_String[iopt];
}

namespace {

  // kappa of the triangles, then eta of the quadrangles, of `mesh`
  std::vector<double> elementQualities(const surfaceMesh &mesh)
  {
    std::vector<double> q;
    q.reserve(mesh.numElements());
    const std::vector<SPoint3> &p = mesh.points;
    for(const auto &t : mesh.triangles)
      q.push_back(triangleKappa(p[t[0]], p[t[1]], p[t[2]]));
    for(const auto &e : mesh.quadrangles)
      q.push_back(quadEta(p[e[0]], p[e[1]], p[e[2]], p[e[3]]));
    return q;
  }

  // The meshes of several faces as one (node numbers offset)
  void append(surfaceMesh &all, const surfaceMesh &m)
  {
    const int offset = (int)all.points.size();
    all.points.insert(all.points.end(), m.points.begin(), m.points.end());
    for(auto t : m.triangles) {
      for(int &n : t) n += offset;
      all.triangles.push_back(t);
    }
    for(auto q : m.quadrangles) {
      for(int &n : q) n += offset;
      all.quadrangles.push_back(q);
    }
  }

  // The elements of the mesh file `name`, merged into a model of its own
  // (the current one is left as it was); false if it has none
  bool readReference(const std::string &name, surfaceMesh &reference)
  {
    GModel *current = GModel::current();
    const char visible = current->getVisibility();
    GModel *own = new GModel();
    GModel::setCurrent(own);
    const bool read = MergeFile(name, true);
    if(read)
      for(auto it = own->firstFace(); it != own->lastFace(); ++it)
        append(reference, surfaceMeshOf(*it));
    delete own;
    GModel::setCurrent(current);
    current->setVisibility(visible);
    return read && reference.numElements() > 0;
  }

  // The measured mesh `all` against the reference file's elements, logged
  void compareToReference(const std::string &name, const surfaceMesh &all)
  {
    surfaceMesh reference;
    if(!readReference(name, reference)) {
      Msg::Warning("SurfaceMeshQuality: no surface mesh in reference '%s'",
                   name.c_str());
      return;
    }
    meshFidelity f = compareToInput(unionAsTriangles({reference}), all);
    const double percent = f.diagonal > 0. ? 100. / f.diagonal : 0.;
    // the minority: the reference may be oriented either way
    Msg::Info("SurfaceMeshQuality: against '%s' (%lu elements): Hausdorff "
              "%.4g%% (mean %.4g%%) of its diagonal, %lu elements pointing "
              "against it",
              name.c_str(), reference.numElements(), percent * f.hausdorff,
              percent * f.meanDistance,
              std::min(f.inverted, f.elements - f.inverted));
  }

} // namespace

PView *GMSH_SurfaceMeshQualityPlugin::execute(PView *v)
{
  const int tag = (int)SurfaceMeshQualityOptions_Number[0].def;
  const bool views = SurfaceMeshQualityOptions_Number[1].def != 0.;
  const int bins = std::max(1, (int)SurfaceMeshQualityOptions_Number[2].def);

  std::vector<GFace *> faces;
  GModel *m = GModel::current();
  for(auto it = m->firstFace(); it != m->lastFace(); ++it)
    if((tag < 0 || (*it)->tag() == tag) && (*it)->getNumMeshElements())
      faces.push_back(*it);
  if(faces.empty()) {
    Msg::Warning("SurfaceMeshQuality: no mesh on %s",
                 tag < 0 ? "any surface" :
                           ("surface " + std::to_string(tag)).c_str());
    return v;
  }

  surfaceMesh all;
  std::size_t compared = 0, inverted = 0, sampled = 0;
  double hausdorff = 0., meanDistance = 0.;
  SBoundingBox3d box;
  for(GFace *gf : faces) {
    surfaceMesh mesh = surfaceMeshOf(gf);
    if(!gf->stl_triangles.empty()) {
      meshFidelity f = compareToInput(inputTriangulationOf(gf), mesh);
      for(const SPoint3 &x : gf->stl_vertices_xyz) box += x;
      compared++;
      // the minority, as Gmsh may orient the face either way
      inverted += std::min(f.inverted, f.elements - f.inverted);
      hausdorff = std::max(hausdorff, f.hausdorff);
      meanDistance += f.meanDistance * f.elements;
      sampled += f.elements;
    }
    append(all, mesh);
  }

  faceQuality q = computeFaceQuality(faces);
  Msg::Info("SurfaceMeshQuality: %lu triangles, kappa min %.4f mean %.4f, "
            "%.2f%% below 0.3",
            q.triangles, q.kappaMin, q.kappaMean, 100. * q.kappaShareBelow03);
  if(q.quadrangles)
    Msg::Info("SurfaceMeshQuality: %lu quadrangles, eta min %.4f mean %.4f",
              q.quadrangles, q.etaMin, q.etaMean);
  Msg::Info("SurfaceMeshQuality: tau %.2f%% over %lu edges", q.tau, q.edges);
  if(compared) {
    const double diagonal = box.empty() ? 0. : box.diag();
    Msg::Info(
      "SurfaceMeshQuality: %lu discrete surfaces: Hausdorff %.4g%% "
      "(mean %.4g%%) of the diagonal of their input, %lu elements "
      "pointing against it",
      compared, diagonal > 0. ? 100. * hausdorff / diagonal : 0.,
      diagonal > 0. && sampled ? 100. * meanDistance / sampled / diagonal : 0.,
      inverted);
  }
  const std::string reference = SurfaceMeshQualityOptions_String[0].def;
  if(!reference.empty()) compareToReference(reference, all);
  if(!views) return v;

  std::vector<double> quality = elementQualities(all);
  const std::size_t numTriangles = all.triangles.size();
  PView *last = nullptr;
  if(numTriangles) {
    surfaceMesh triangles = all;
    triangles.quadrangles.clear();
    std::vector<double> kappa(quality.begin(), quality.begin() + numTriangles);
    elementValueView("kappa", triangles, kappa);
    last = histogramView("kappa", histogram(kappa, bins, 0., 1.), 0., 1.);
  }
  if(all.quadrangles.size()) {
    surfaceMesh quadrangles = all;
    quadrangles.triangles.clear();
    std::vector<double> eta(quality.begin() + numTriangles, quality.end());
    elementValueView("eta", quadrangles, eta);
    last = histogramView("eta", histogram(eta, bins, 0., 1.), 0., 1.);
  }
  return last ? last : v;
}
