// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Plugin(SurfaceMeshQuality): quality of any surface mesh (stock Gmsh meshes
// too): kappa, eta, tau and, for discrete faces, the distance to their input
// triangulation, or to a reference mesh file for any mesh (another
// remesher's output against its input); views of kappa / eta per element
// and their histograms.

#ifndef SURFACE_MESH_QUALITY_H
#define SURFACE_MESH_QUALITY_H

#include "Plugin.h"

class GMSH_SurfaceMeshQualityPlugin : public GMSH_PostPlugin {
public:
  std::string getName() const { return "SurfaceMeshQuality"; }
  std::string getShortHelp() const
  {
    return "Quality (kappa, eta, tau) of surface meshes, with views";
  }
  std::string getHelp() const;
  std::string getAuthor() const { return "Reparam"; }
  int getNbOptions() const;
  StringXNumber *getOption(int iopt);
  int getNbOptionsStr() const;
  StringXString *getOptionStr(int iopt);
  PView *execute(PView *);
};

#endif
