// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file layer_toggles.h
 *  \brief Named layers of what a RegistrationVisualizer shows (the scan, the fit, landmarks, correspondences), each
 *  shown or hidden by a key in its window, with a legend of the keys.
 */
#include <morphreg/visualization/registration_visualizer.h>

#include <boost/signals2/connection.hpp>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief Layers of shapes toggled together by a key.
 *
 *  \code
 *  morphreg::LayerToggles layers (viewer);
 *  layers.addLayer ("scan", 't', {"scan"});
 *  layers.addLayer ("fit", 'm', {"fit"});        // a residual heat map's colour bar goes with it
 *  layers.connectKeys ();                         // window only: the keys and a legend
 *  viewer.spin ();
 *  \endcode
 */
class LayerToggles
{
public:
  /** \brief Layers over \a viewer's shapes; \a viewer must outlive this object. */
  explicit LayerToggles (RegistrationVisualizer& viewer);

  /** \brief Disconnects the keys. */
  ~LayerToggles ();

  /// \cond
  LayerToggles (const LayerToggles&) = delete;
  LayerToggles&
  operator= (const LayerToggles&) = delete;
  /// \endcond

  /** \brief Adds a layer of shapes already shown. Throws InvalidInputError for a key PCLVisualizer uses itself
   *  (p w s j c f e q g u r l x h, digits, + -), a key or name taken, no ids, or an id nothing is shown under.
   *  \param[in] name the layer's name in the legend
   *  \param[in] key the key that toggles it (a letter)
   *  \param[in] ids the shapes' ids
   */
  void
  addLayer (const std::string& name, char key, const std::vector<std::string>& ids);

  /** \brief Shows or hides a layer's shapes. Throws InvalidInputError for an unknown layer.
   *  \param[in] name the layer
   *  \param[in] visible whether it is drawn
   */
  void
  setVisible (const std::string& name, bool visible);

  /** \brief Whether a layer is shown. Throws InvalidInputError for an unknown layer.
   *  \param[in] name the layer
   *  \return its visibility
   */
  bool
  isVisible (const std::string& name) const;

  /** \brief Toggles the layer of \a key, as a key press in the window does.
   *  \param[in] key the key
   *  \return whether a layer has that key
   */
  bool
  toggle (char key);

  /** \brief The keys and the layers' states, e.g. "keys: t scan (on)  m fit (off)".
   *  \return the legend
   */
  std::string
  legend () const;

  /** \brief Makes the window's keys toggle the layers and writes the legend in its top-left corner. */
  void
  connectKeys ();

private:
  struct Layer
  {
    std::string name;
    char key;
    std::vector<std::string> ids;
    bool visible;
  };

  const Layer&
  layer (const std::string& name) const;

  void
  showLegend ();

  RegistrationVisualizer& viewer_;
  std::vector<Layer> layers_;
  boost::signals2::connection keys_;
  bool legend_shown_ = false;
};
} // namespace morphreg
