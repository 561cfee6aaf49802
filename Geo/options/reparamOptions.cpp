// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <cmath>
#include <string>
#include "GmshMessage.h"
#include "Options.h"
#include "reparamHooks.h"
#include "reparamOptions.h"
#include "reparamOptionsWindow.h"

namespace reparam {

reparamOptions &getReparamOptions()
{
  static reparamOptions options;
  return options;
}

} // namespace reparam

using namespace reparam;

namespace reparam {

// An integer option from lo to hi, shown in the options window: another value
// is refused with an error (`what` names the value kept), the option kept
static double integerOption(int &option, int lo, int hi, const char *name,
                            const std::string &what, compoundWidget widget,
                            int action, double val)
{
  if(action & GMSH_SET) {
    const int value = (int)val;
    if(value != val || value < lo || value > hi)
      Msg::Error("%s must be an integer from %d to %d (got %g): keeping %d%s",
                 name, lo, hi, val, option, what.c_str());
    else
      option = value;
  }
  if(action & GMSH_GUI) showInOptionsWindow(widget, option);
  return option;
}

} // namespace reparam

double opt_mesh_compound_parametrization(OPT_ARGS_NUM)
{
  int &p = getReparamOptions().parametrization;
  return integerOption(p, 0, 6, "Mesh.CompoundParametrization",
                       std::string(" (") + compoundParametrizationName(p) + ")",
                       compoundWidget::parametrization, action, val);
}

namespace reparam {

// The on/off options: any nonzero value sets them
static double onOffOption(bool &option, int action, double val)
{
  if(action & GMSH_SET) option = (val != 0.);
  return option ? 1. : 0.;
}

// ... and those the options window shows
static double onOffOption(bool &option, compoundWidget widget, int action,
                          double val)
{
  const double value = onOffOption(option, action, val);
  if(action & GMSH_GUI) showInOptionsWindow(widget, value);
  return value;
}

} // namespace reparam

double opt_mesh_compound_fill_holes(OPT_ARGS_NUM)
{
  return onOffOption(getReparamOptions().fillHoles, compoundWidget::fillHoles,
                     action, val);
}

double opt_mesh_compound_repair(OPT_ARGS_NUM)
{
  return onOffOption(getReparamOptions().repair, compoundWidget::repair, action,
                     val);
}

double opt_mesh_compound_split(OPT_ARGS_NUM)
{
  return onOffOption(getReparamOptions().split, compoundWidget::split, action,
                     val);
}

double opt_mesh_compound_layout(OPT_ARGS_NUM)
{
  return onOffOption(getReparamOptions().layout, action, val);
}

double opt_mesh_compound_curve_corners(OPT_ARGS_NUM)
{
  return onOffOption(getReparamOptions().curveCorners, action, val);
}

double opt_mesh_compound_optimize(OPT_ARGS_NUM)
{
  return integerOption(getReparamOptions().optimize, 0, 2,
                       "Mesh.CompoundOptimize", "", compoundWidget::optimize,
                       action, val);
}

namespace reparam {

namespace {

  // A finite value >= 0, else an error and the old value kept
  double nonNegativeOption(double &value, const char *name, int action,
                           double val)
  {
    if(action & GMSH_SET) {
      if(!(val >= 0.) || !std::isfinite(val))
        Msg::Error("Mesh.%s must be >= 0 (got %g): keeping %g", name, val,
                   value);
      else
        value = val;
    }
    return value;
  }

} // namespace

} // namespace reparam

double opt_mesh_compound_curvature_metric(OPT_ARGS_NUM)
{
  const double value =
    nonNegativeOption(getReparamOptions().curvatureMetric,
                      "CompoundCurvatureMetric", action, val);
  if(action & GMSH_GUI)
    showInOptionsWindow(compoundWidget::curvatureMetric, value);
  return value;
}

double opt_mesh_compound_noise_size(OPT_ARGS_NUM)
{
  return nonNegativeOption(getReparamOptions().noiseSize, "CompoundNoiseSize",
                           action, val);
}

double opt_mesh_compound_feature_scale(OPT_ARGS_NUM)
{
  return nonNegativeOption(getReparamOptions().featureScale,
                           "CompoundFeatureScale", action, val);
}

double opt_mesh_compound_mesh_size_gradient(OPT_ARGS_NUM)
{
  return nonNegativeOption(getReparamOptions().meshSizeGradient,
                           "CompoundMeshSizeGradient", action, val);
}

double opt_mesh_compound_mesh_size_from_strips(OPT_ARGS_NUM)
{
  double v = getReparamOptions().meshSizeFromStrips;
  nonNegativeOption(v, "CompoundMeshSizeFromStrips", action, val);
  getReparamOptions().meshSizeFromStrips = v > 0.;
  return getReparamOptions().meshSizeFromStrips;
}

double opt_mesh_compound_report(OPT_ARGS_NUM)
{
  return onOffOption(getReparamOptions().report, compoundWidget::report, action,
                     val);
}

std::string opt_mesh_compound_report_file(OPT_ARGS_STR)
{
  reparamOptions &o = getReparamOptions();
  if(action & GMSH_SET) o.reportFile = val;
  return o.reportFile;
}
