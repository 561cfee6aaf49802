// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "GModel.h"
#include "PluginManager.h"
#include "SurfaceMeshQuality.h"
#include "triangleQuality.h"

StringXNumber SurfaceMeshQualityOptions_Number[] = {
  {GMSH_FULLRC, "Surface", nullptr, -1.}};

// Registered with Gmsh's plugin manager when libgmsh is loaded
static GMSH_Plugin *createSurfaceMeshQualityPlugin()
{
  return new GMSH_SurfaceMeshQualityPlugin();
}
static const bool surfaceMeshQualityRegistered =
  (PluginManager::addPluginFactory("SurfaceMeshQuality",
                                   createSurfaceMeshQualityPlugin),
   true);

std::string GMSH_SurfaceMeshQualityPlugin::getHelp() const
{
  return "Plugin(SurfaceMeshQuality) prints the number of triangles of "
         "surface `Surface' (of all surfaces if `Surface' < 0) and their "
         "aspect ratio kappa = 4 sin a sin b sin c / (sin a + sin b + sin c): "
         "minimum, mean and share below 0.3.";
}

int GMSH_SurfaceMeshQualityPlugin::getNbOptions() const
{
  return sizeof(SurfaceMeshQualityOptions_Number) / sizeof(StringXNumber);
}

StringXNumber *GMSH_SurfaceMeshQualityPlugin::getOption(int iopt)
{
  return &SurfaceMeshQualityOptions_Number[iopt];
}

PView *GMSH_SurfaceMeshQualityPlugin::execute(PView *v)
{
  int tag = (int)SurfaceMeshQualityOptions_Number[0].def;
  std::vector<MTriangle *> triangles;
  GModel *m = GModel::current();
  for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
    if(tag >= 0 && (*it)->tag() != tag) continue;
    triangles.insert(triangles.end(), (*it)->triangles.begin(),
                     (*it)->triangles.end());
  }
  if(triangles.empty()) {
    Msg::Warning("SurfaceMeshQuality: no triangle on %s", tag < 0 ?
                 "any surface" : ("surface " + std::to_string(tag)).c_str());
    return v;
  }
  kappaStatistics k = computeKappaStatistics(triangles);
  Msg::Info("SurfaceMeshQuality: %lu triangles, kappa min %.4f mean %.4f, "
            "%.2f%% below 0.3",
            k.triangles, k.min, k.mean, 100. * k.shareBelow03);
  return v;
}
