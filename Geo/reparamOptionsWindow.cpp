// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "GmshConfig.h"
#include "reparamOptionsWindow.h"
#if defined(HAVE_FLTK)
#include "FlGui.h"
#include "optionWindow.h"
#endif

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

#else

void showInOptionsWindow(compoundWidget, double) {}

#endif
