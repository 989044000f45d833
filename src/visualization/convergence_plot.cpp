// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/visualization/convergence_plot.h>

#include "window_png.h"

#include <morphreg/visualization/x_display.h>

#include <vtkAutoInit.h>
#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>

VTK_MODULE_INIT (vtkRenderingContextOpenGL2)

namespace morphreg
{
namespace
{
/** The iterations of \a stage as (iteration, RMS mm) columns; the shape stage starts from the similarity stage's last
 *  iteration so the two lines join. */
vtkSmartPointer<vtkTable>
stageTable (const IcpReport& report, IcpStage stage, const char* name)
{
  auto iterations = vtkSmartPointer<vtkDoubleArray>::New ();
  iterations->SetName ("iteration");
  auto rms = vtkSmartPointer<vtkDoubleArray>::New ();
  rms->SetName (name);
  for (std::size_t i = 0; i < report.history.size (); ++i) {
    const bool joins = i + 1 < report.history.size () && report.history[i + 1].stage == stage;
    if (report.history[i].stage != stage && !(stage == IcpStage::shape && joins))
      continue;
    iterations->InsertNextValue (static_cast<double> (i + 1));
    rms->InsertNextValue (std::sqrt (std::max (report.history[i].error, 0.0)));
  }
  auto table = vtkSmartPointer<vtkTable>::New ();
  table->AddColumn (iterations);
  table->AddColumn (rms);
  return table;
}

void
addStage (vtkChartXY& chart, const IcpReport& report, IcpStage stage, const char* name, const unsigned char rgb[3])
{
  const vtkSmartPointer<vtkTable> table = stageTable (report, stage, name);
  if (table->GetNumberOfRows () == 0)
    return;
  vtkPlot* line = chart.AddPlot (vtkChart::LINE);
  line->SetInputData (table, 0, 1);
  line->SetColor (rgb[0], rgb[1], rgb[2], 255);
  line->SetWidth (2.5);
}

void
styleAxis (vtkAxis* axis, const char* title)
{
  axis->SetTitle (title);
  axis->GetTitleProperties ()->SetFontSize (16);
  axis->GetTitleProperties ()->BoldOff ();
  axis->GetLabelProperties ()->SetFontSize (14);
}
} // namespace

void
saveConvergencePlot (const std::string& png_path, const IcpReport& report, const std::string& title, int width,
                     int height)
{
  if (report.history.empty ())
    throw InvalidInputError ("saveConvergencePlot: " + png_path + ": the registration ran no iteration");
  if (width < 160 || height < 120)
    throw InvalidInputError ("saveConvergencePlot: " + png_path + ": size " + std::to_string (width) + "x" +
                             std::to_string (height) + " is under 160x120");
  requireXDisplay ("saveConvergencePlot");
  auto view = vtkSmartPointer<vtkContextView>::New ();
  view->GetRenderWindow ()->SetOffScreenRendering (1);
  view->GetRenderWindow ()->SetSize (width, height);
  view->GetRenderer ()->SetBackground (1.0, 1.0, 1.0);
  auto chart = vtkSmartPointer<vtkChartXY>::New ();
  view->GetScene ()->AddItem (chart);
  const unsigned char similarity[3] = {230, 120, 20}, shape[3] = {40, 90, 200};
  addStage (*chart, report, IcpStage::similarity, "similarity stage", similarity);
  addStage (*chart, report, IcpStage::shape, "shape stage", shape);
  styleAxis (chart->GetAxis (vtkAxis::BOTTOM), "iteration");
  styleAxis (chart->GetAxis (vtkAxis::LEFT), "RMS distance to the scan (mm)");
  chart->GetAxis (vtkAxis::LEFT)->SetMinimum (0.0);
  chart->GetAxis (vtkAxis::LEFT)->SetBehavior (vtkAxis::FIXED);
  double largest = 0.0;
  for (const IcpIteration& iteration : report.history)
    largest = std::max (largest, std::sqrt (std::max (iteration.error, 0.0)));
  chart->GetAxis (vtkAxis::LEFT)->SetMaximum (largest > 0.0 ? 1.08 * largest : 1.0);
  chart->SetTitle (title.empty () ? "convergence" : title);
  chart->GetTitleProperties ()->SetFontSize (16);
  chart->SetShowLegend (true);
  chart->GetLegend ()->GetLabelProperties ()->SetFontSize (14);
  detail::writeWindowPng (*view->GetRenderWindow (), png_path);
}
} // namespace morphreg
