// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/visualization/layer_toggles.h>

#include <pcl/visualization/pcl_visualizer.h>

#include <algorithm>
#include <cctype>
#include <cstring>

namespace morphreg
{
namespace
{
/** The keys PCLVisualizer's interactor handles itself (either case). */
bool
isPclKey (char key)
{
  static const char kTaken[] = "pwsjcfeqgurlxh+-";
  const char lower = static_cast<char> (std::tolower (static_cast<unsigned char> (key)));
  return std::strchr (kTaken, lower) != nullptr || std::isdigit (static_cast<unsigned char> (key));
}
} // namespace

LayerToggles::LayerToggles (RegistrationVisualizer& viewer) : viewer_ (viewer) {}

LayerToggles::~LayerToggles ()
{
  keys_.disconnect ();
}

void
LayerToggles::addLayer (const std::string& name, char key, const std::vector<std::string>& ids)
{
  const std::string what = "LayerToggles::addLayer '" + name + "': ";
  if (!std::isalpha (static_cast<unsigned char> (key)) || isPclKey (key))
    throw InvalidInputError (what + "key '" + std::string (1, key) +
                             "' is not a letter PCLVisualizer leaves free (not p w s j c f e q g u r l x h)");
  for (const Layer& other : layers_)
    if (other.name == name || other.key == key)
      throw InvalidInputError (what + "the name or the key '" + std::string (1, key) + "' is taken by '" + other.name +
                               "'");
  if (ids.empty ())
    throw InvalidInputError (what + "no shapes");
  for (const std::string& id : ids)
    viewer_.setVisibility (id, true); // throws for an id nothing is shown under
  layers_.push_back ({name, key, ids, true});
  showLegend ();
}

const LayerToggles::Layer&
LayerToggles::layer (const std::string& name) const
{
  const auto found = std::find_if (layers_.begin (), layers_.end (), [&] (const Layer& l) { return l.name == name; });
  if (found == layers_.end ())
    throw InvalidInputError ("LayerToggles: no layer '" + name + "'");
  return *found;
}

void
LayerToggles::setVisible (const std::string& name, bool visible)
{
  const Layer& shown = layer (name);
  for (const std::string& id : shown.ids)
    viewer_.setVisibility (id, visible);
  layers_[static_cast<std::size_t> (&shown - layers_.data ())].visible = visible;
  showLegend ();
}

bool
LayerToggles::isVisible (const std::string& name) const
{
  return layer (name).visible;
}

bool
LayerToggles::toggle (char key)
{
  for (const Layer& candidate : layers_)
    if (candidate.key == key) {
      setVisible (candidate.name, !candidate.visible);
      return true;
    }
  return false;
}

std::string
LayerToggles::legend () const
{
  std::string text = "keys:";
  for (const Layer& l : layers_)
    text += std::string ("  ") + l.key + " " + l.name + (l.visible ? " (on)" : " (off)");
  return text;
}

void
LayerToggles::connectKeys ()
{
  keys_.disconnect ();
  keys_ = viewer_.getVisualizer ().registerKeyboardCallback ([this] (const pcl::visualization::KeyboardEvent& event) {
    if (event.keyDown () && toggle (event.getKeyCode ()))
      viewer_.getVisualizer ().getRenderWindow ()->Render ();
  });
  legend_shown_ = true;
  showLegend ();
}

void
LayerToggles::showLegend ()
{
  if (!legend_shown_)
    return;
  pcl::visualization::PCLVisualizer& visualizer = viewer_.getVisualizer ();
  if (!visualizer.updateText (legend (), 10, 10, 14, 0.1, 0.1, 0.1, "layer_legend"))
    visualizer.addText (legend (), 10, 10, 14, 0.1, 0.1, 0.1, "layer_legend");
}
} // namespace morphreg
