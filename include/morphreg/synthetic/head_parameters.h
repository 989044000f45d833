// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file head_parameters.h
 *  \brief The anthropometric parameters (mm) that shape a synthetic head, with plausible population ranges.
 */
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace morphreg
{
namespace synthetic
{
/** \brief Head measurements in millimetres. Defaults are the population means (adult, mixed sex); amplitudes
 *  (projections, thicknesses, depths) are heights of a feature above the surrounding surface.
 */
struct HeadParameters
{
  double head_length = 192.0;    ///< glabella to opisthocranion
  double head_breadth = 150.0;   ///< euryon to euryon (widest skull breadth)
  double head_height = 228.0;    ///< vertex (top of the skull) to menton (bottom of the chin)
  double face_width = 136.0;     ///< bizygomatic breadth (across the cheekbones)
  double jaw_width = 106.0;      ///< bigonial breadth (across the jaw angles)
  double nose_length = 50.0;     ///< nasion to subnasale
  double nose_width = 35.0;      ///< alar breadth (across the nose wings)
  double nose_projection = 19.0; ///< how far the nose tip stands out of the face
  double mouth_width = 50.0;     ///< mouth corner to mouth corner
  double lip_thickness = 8.0;    ///< how far the lips stand out
  double chin_projection = 7.0;  ///< how far the chin stands out of the jaw
  double eye_separation = 63.0;  ///< distance between the eye centres
  double eye_depth = 7.0;        ///< depth of the eye sockets
  double brow_ridge = 5.0;       ///< height of the brow ridge
  double cheek_fullness = 5.0;   ///< height of the cheeks over the face
  double ear_length = 62.0;      ///< ear top to earlobe bottom
  double ear_protrusion = 17.0;  ///< how far the ears stand off the head
  double ear_height = 0.0;       ///< vertical offset of the ears from their mean position
  double neck_girth = 360.0;     ///< circumference of the neck
  double neck_length = 75.0;     ///< from the chin down to where the neck is cut

  /** \brief Name, mean, standard deviation and allowed range of one parameter. */
  struct Range
  {
    std::string name;               ///< the member's name, e.g. "nose_length"
    double HeadParameters::*member; ///< the member it describes
    double mean;                    ///< population mean, mm
    double stddev;                  ///< population standard deviation, mm
    double min;                     ///< smallest allowed value, mm
    double max;                     ///< largest allowed value, mm
  };

  /** \brief All parameters with their population statistics (the order of asVector()).
   *  \return one range per parameter
   */
  static const std::vector<Range>&
  ranges ();

  /** \brief Draws a head from the population: a shared size factor (half of every length's variance) plus
   *  independent Gaussian variation, each value clamped to its range (mean +- 2.5 sd).
   *  \param[in,out] rng the random generator
   *  \return the drawn parameters
   */
  static HeadParameters
  sample (std::mt19937_64& rng);

  /** \brief The parameters in the order of ranges().
   *  \return their values, mm
   */

  std::vector<double>
  asVector () const;

  /** \brief Throws InvalidInputError naming the parameter if one is outside its range or not finite. */
  void
  validate () const;
};

} // namespace synthetic
} // namespace morphreg
