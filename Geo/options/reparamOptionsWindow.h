// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Reparam's options in Gmsh's options window: the Compound tab of Tools >
// Options > Mesh (patches/0017) sets them through their accessors
// (Geo/options/reparamOptions.cpp), which show their values back in its widgets,
// as Gmsh's own accessors do (action GMSH_GUI). Nothing without the GUI.

#ifndef REPARAM_OPTIONS_WINDOW_H
#define REPARAM_OPTIONS_WINDOW_H

class Fl_Widget;
class optionWindow;

namespace reparam {

enum class compoundWidget {
  parametrization, // a choice of the 7 maps: optionWindow::mesh.choice[40]
  optimize, // a choice of 0, 1, 2: mesh.choice[41]
  repair, // check buttons: mesh.butt[40]
  fillHoles, // mesh.butt[41]
  split, // mesh.butt[42]
  report, // mesh.butt[43]
  curvatureMetric // a value: mesh.value[40]
};

// Shows value in the widget, if Gmsh's window exists
void showInOptionsWindow(compoundWidget widget, double value);

// The hooks (patches/0017), with the GUI only. The Compound tab, in the
// group of the mesh options' tabs being built, at (x, y), w x h, its
// check buttons bw wide; `changed`: the callback of Gmsh's mesh options,
// which calls reparamApplyCompoundTab
} // namespace reparam

#endif
