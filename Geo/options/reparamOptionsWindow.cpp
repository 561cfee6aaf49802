// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "GmshConfig.h"
#include "reparamHooks.h"
#include "reparamOptionsWindow.h"
#if defined(HAVE_FLTK)
#include "Context.h"
#include "FlGui.h"
#include "Options.h"
#include "optionWindow.h"
#endif

namespace reparam {

#if defined(HAVE_FLTK)

void showInOptionsWindow(compoundWidget widget, double value)
{
  if(!FlGui::available()) return;
  optionWindow *o = FlGui::instance()->options;
  switch(widget) {
  case compoundWidget::parametrization:
    o->mesh.choice[40]->value((int)value);
    break;
  case compoundWidget::optimize: o->mesh.choice[41]->value((int)value); break;
  case compoundWidget::repair: o->mesh.butt[40]->value(value != 0.); break;
  case compoundWidget::fillHoles: o->mesh.butt[41]->value(value != 0.); break;
  case compoundWidget::split: o->mesh.butt[42]->value(value != 0.); break;
  case compoundWidget::report: o->mesh.butt[43]->value(value != 0.); break;
  case compoundWidget::curvatureMetric: o->mesh.value[40]->value(value); break;
  }
}

} // namespace reparam

using namespace reparam;

// Reparam's accessors (Geo/options/reparamOptions.cpp)
double opt_mesh_compound_parametrization(OPT_ARGS_NUM);

double opt_mesh_compound_optimize(OPT_ARGS_NUM);

double opt_mesh_compound_repair(OPT_ARGS_NUM);

double opt_mesh_compound_fill_holes(OPT_ARGS_NUM);

double opt_mesh_compound_split(OPT_ARGS_NUM);

double opt_mesh_compound_report(OPT_ARGS_NUM);

double opt_mesh_compound_curvature_metric(OPT_ARGS_NUM);

void reparamAddCompoundTab(optionWindow *w, int x, int y, int width, int height,
                           int bw, void (*changed)(Fl_Widget *, void *))
{
  Fl_Group *o = new Fl_Group(x, y, width, height, "Compound");
  o->hide();
  // the rows of the other tabs: from WB inside the group, BH apart
  auto row = [&](int i) { return y + WB + (i - 1) * BH; };
  const int left = x + WB;

  // short labels that fit the choice at Gmsh's default window size; the
  // long names in the tooltips
  static Fl_Menu_Item menu_compound_map[] = {
    {"Gmsh built-in", 0, nullptr, nullptr},
    {"FE harmonic", 0, nullptr, nullptr},
    {"Barycentric", 0, nullptr, nullptr},
    {"Mean value", 0, nullptr, nullptr},
    {"FE conformal", 0, nullptr, nullptr},
    {"Spectral", 0, nullptr, nullptr},
    {"Automatic", 0, nullptr, nullptr},
    {nullptr}};
  static Fl_Menu_Item menu_compound_optimize[] = {
    {"None", 0, nullptr, nullptr},
    {"No collapses", 0, nullptr, nullptr},
    {"Full", 0, nullptr, nullptr},
    {nullptr}};
  auto choice = [&](int i, int r, const char *label, Fl_Menu_Item *menu,
                    const char *tip) {
    Fl_Choice *c = w->mesh.choice[i] =
      new Fl_Choice(left, row(r), IW, BH, label);
    c->menu(menu);
    c->align(FL_ALIGN_RIGHT);
    c->tooltip(tip);
    c->callback(changed);
  };
  choice(40, 1, "Parametrization", menu_compound_map,
         "Mesh.CompoundParametrization: 0 Gmsh's built-in map, 1 finite "
         "element harmonic, 2 barycentric (Tutte), 3 mean value, 4 finite "
         "element conformal (LSCM), 5 spectral conformal, 6 automatic (the "
         "first one-to-one map of a chain). A change after the geometry is "
         "created acts at the next mesh: the surfaces are parametrized again");
  choice(41, 2, "Optimization", menu_compound_optimize,
         "Mesh.CompoundOptimize: the new mesh optimized on the input; 0 none, "
         "1 without collapses of short edges, 2 with them");

  const char *buttons[] = {"Repair flipped parametric triangles",
                           "Fill holes before mapping",
                           "Split the patches no map flattens well",
                           "Report quality and distance after meshing"};
  const char *tips[] = {
    "Mesh.CompoundRepair (acts at the next mesh)",
    "Mesh.CompoundFillHoles (acts at the next mesh)",
    "Mesh.CompoundSplit (read by ClassifySurfaces, with Mesh.CompoundLayout "
    "= 0: reload the file after a change)",
    "Mesh.CompoundReport"};
  for(int i = 0; i < 4; i++) {
    Fl_Check_Button *b = w->mesh.butt[40 + i] =
      new Fl_Check_Button(left, row(3 + i), bw, BH, buttons[i]);
    b->tooltip(tips[i]);
    b->type(FL_TOGGLE_BUTTON);
    b->callback(changed);
  }

  Fl_Value_Input *curvature = w->mesh.value[40] = new Fl_Value_Input(
    left, row(7), IW / 2, BH, "Anisotropic sizes from curvature (BAMG)");
  curvature->tooltip("Mesh.CompoundCurvatureMetric (number of elements per "
                     "2 * Pi radians; 0: off)");
  curvature->minimum(0);
  curvature->maximum(100);
  if(CTX::instance()->inputScrolling) curvature->step(1);
  curvature->align(FL_ALIGN_RIGHT);
  curvature->callback(changed);

  o->end();
}

void reparamApplyCompoundTab(optionWindow *o)
{
  opt_mesh_compound_parametrization(0, GMSH_SET, o->mesh.choice[40]->value());
  opt_mesh_compound_optimize(0, GMSH_SET, o->mesh.choice[41]->value());
  opt_mesh_compound_repair(0, GMSH_SET, o->mesh.butt[40]->value());
  opt_mesh_compound_fill_holes(0, GMSH_SET, o->mesh.butt[41]->value());
  opt_mesh_compound_split(0, GMSH_SET, o->mesh.butt[42]->value());
  opt_mesh_compound_report(0, GMSH_SET, o->mesh.butt[43]->value());
  opt_mesh_compound_curvature_metric(0, GMSH_SET, o->mesh.value[40]->value());
}

namespace reparam {

#else

void showInOptionsWindow(compoundWidget, double) {}
} // namespace reparam

void reparamAddCompoundTab(optionWindow *, int, int, int, int, int,
                           void (*)(Fl_Widget *, void *))
{
}

void reparamApplyCompoundTab(optionWindow *) {}

namespace reparam {

#endif
} // namespace reparam

