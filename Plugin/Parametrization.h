// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Plugin(Parametrization): shows the (u, v) parametrization of discrete and
// compound surfaces (paper Fig. 5, 15, 16): u and v on the 3D surface, the
// flattened triangulation, and how far each triangle is from conformal and
// from area preserving.

#ifndef PARAMETRIZATION_PLUGIN_H
#define PARAMETRIZATION_PLUGIN_H

#include "Plugin.h"

class GMSH_ParametrizationPlugin : public GMSH_PostPlugin {
public:
  std::string getName() const { return "Parametrization"; }
  std::string getShortHelp() const
  {
    return "Views of the (u, v) parametrization of discrete surfaces";
  }
  std::string getHelp() const;
  std::string getAuthor() const { return "Reparam"; }
  int getNbOptions() const;
  StringXNumber *getOption(int iopt);
  PView *execute(PView *);
};

#endif
