// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Registration of Reparam's plugins with Gmsh's plugin manager, from a
// static initializer, when libgmsh is loaded (patches/0003)

#ifndef REPARAM_PLUGIN_REGISTRATION_H
#define REPARAM_PLUGIN_REGISTRATION_H

#include "PluginManager.h"

// static const bool registered = registerReparamPlugin<GMSH_XPlugin>("X");
template <class PluginClass> bool registerReparamPlugin(const char *name)
{
  PluginManager::addPluginFactory(
    name, []() -> GMSH_Plugin * { return new PluginClass(); });
  return true;
}

#endif
