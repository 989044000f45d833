// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the library: numbers in the sentences of error messages and reports.
#include <sstream>
#include <string>

namespace morphreg
{
namespace detail
{
/** \a value with \a digits significant digits ("0.000123", "120", "25.4"), as a message quotes a measurement. */
inline std::string
numberText (double value, int digits = 3)
{
  std::ostringstream text;
  text.precision (digits);
  text << value;
  return text.str ();
}
} // namespace detail
} // namespace morphreg
