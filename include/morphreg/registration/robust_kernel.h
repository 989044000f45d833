// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file robust_kernel.h
 *  \brief The robust (IRLS) kernels of the registrations as objects: each a weight of the residual distance with
 *  its own width, automatic (from the residuals' spread) or fixed. The kernels are in kernels/, one file each, and
 *  are made by name in one place (makeRobustKernel), where a new kernel is registered.
 */
#include <memory>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief An IRLS kernel: a correspondence at residual distance d weighs weight (d / c), c the kernel's width. */
class RobustKernel
{
public:
  using Ptr = std::shared_ptr<RobustKernel>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const RobustKernel>; ///< shared pointer to const

  /** \param[in] scale the width c (mm), or <= 0 for the automatic one (see width()) */
  explicit RobustKernel (double scale = 0.0);
  virtual ~RobustKernel () = default;

  /** \brief The kernel's name as settings and reports give it.
   *  \return e.g. "huber" */
  virtual std::string
  name () const = 0;

  /** \brief The IRLS weight of a residual at \a u = d / c widths; 1 at 0.
   *  \param[in] u the residual distance in kernel widths (>= 0)
   *  \return the weight in [0, 1] */
  virtual double
  weightAt (double u) const = 0;

  /** \brief The width of the automatic scale in robust standard deviations: the constant giving 95 % efficiency
   *  under Gaussian residuals (Huber 1.345, Tukey 4.685).
   *  \return the constant */
  virtual double
  tuningConstant () const = 0;

  /** \brief The kernel that the phases before the last of a graduated fit use (MorphableICP::
   *  setGraduatedRobustLoss); nullptr, the default: this one throughout. A redescending kernel, which gives no
   *  weight to what is still far, hands the early phases to a convex one.
   *  \return the kernel of the early phases, or nullptr */
  virtual ConstPtr
  graduatedStart () const
  {
    return nullptr;
  }

  /** \brief The width c for residual distances \a distances: the fixed scale, else tuningConstant() times the
   *  robust standard deviation 1.4826 MAD (their median absolute value), at least 1e-6 mm.
   *  \param[in] distances the residual distances (mm, >= 0)
   *  \return c (mm) */
  double
  width (const std::vector<double>& distances) const;

  /** \brief The IRLS weight of a residual distance.
   *  \param[in] distance the residual distance d (mm, >= 0)
   *  \param[in] width the kernel width c (mm, > 0)
   *  \return weightAt (d / c) */
  double
  weight (double distance, double width) const
  {
    return weightAt (distance / width);
  }

  /** \brief The fixed width.
   *  \return mm, or 0 for the automatic one */
  double
  getScale () const
  {
    return scale_;
  }

private:
  double scale_;
};

/** \brief The names of the registered kernels, in the order settings list them ("none", "huber", ...).
 *  \return the names
 */
const std::vector<std::string>&
robustKernelNames ();

/** \brief A registered kernel by name; InvalidInputError naming \a name and the known ones otherwise.
 *  \param[in] name one of robustKernelNames()
 *  \param[in] scale the width c (mm), or <= 0 for the automatic one
 *  \return the kernel
 */
RobustKernel::Ptr
makeRobustKernel (const std::string& name, double scale = 0.0);

} // namespace morphreg
