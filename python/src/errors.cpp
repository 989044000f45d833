// SPDX-License-Identifier: BSD-3-Clause
// morphreg's exceptions as Python classes with the same names and messages. Each also derives from the Python
// exception a caller would expect: InvalidInputError is a ValueError, IoError an OSError, NumericalError an
// ArithmeticError.
#include "bindings.h"

#include <morphreg/common/error.h>

#include <cstring>
#include <string>

namespace morphreg
{
namespace python
{
namespace
{
/** A new exception class morphreg.<name> with \a bases, added to \a m (which keeps it alive). */
PyObject*
addException (py::module_& m, const char* name, const char* doc, py::tuple bases)
{
  const std::string qualified = std::string ("morphreg.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc (qualified.c_str (), doc, bases.ptr (), nullptr);
  if (!type)
    throw py::error_already_set ();
  m.add_object (name, py::reinterpret_steal<py::object> (type));
  return type;
}

/** Raises \a type with \a message; bytes that are not UTF-8 (quoted from a corrupt file) become \\x escapes. */
void
raise (PyObject* type, const char* message)
{
  PyObject* text = PyUnicode_DecodeUTF8 (message, static_cast<Py_ssize_t> (std::strlen (message)), "backslashreplace");
  PyErr_SetObject (type, text);
  Py_XDECREF (text);
}
} // namespace

void
bindErrors (py::module_& m)
{
  // Raw pointers: the module owns the classes, and statics holding references would outlive the interpreter.
  static PyObject *error, *invalid, *too_few, *io, *format, *numerical;
  const auto builtin = [] (PyObject* type) { return py::reinterpret_borrow<py::object> (type); };
  error = addException (m, "Error", "Base of every morphreg error.", py::make_tuple (builtin (PyExc_Exception)));
  invalid = addException (m, "InvalidInputError", "Invalid arguments or data (also a ValueError).",
                          py::make_tuple (builtin (error), builtin (PyExc_ValueError)));
  too_few = addException (m, "TooFewCorrespondencesError", "A registration lost its target.",
                          py::make_tuple (builtin (invalid)));
  io = addException (m, "IoError", "A file is missing, unreadable or cannot be written (also an OSError).",
                     py::make_tuple (builtin (error), builtin (PyExc_OSError)));
  format = addException (m, "FormatError", "A file's content is corrupt, truncated or of the wrong shape.",
                         py::make_tuple (builtin (io)));
  numerical = addException (m, "NumericalError", "No trustworthy answer (also an ArithmeticError).",
                            py::make_tuple (builtin (error), builtin (PyExc_ArithmeticError)));
  // Most derived first: a translator sees the exception as thrown.
  py::register_exception_translator ([] (std::exception_ptr thrown) {
    try {
      if (thrown)
        std::rethrow_exception (thrown);
    }
    catch (const TooFewCorrespondencesError& e) {
      raise (too_few, e.what ());
    }
    catch (const InvalidInputError& e) {
      raise (invalid, e.what ());
    }
    catch (const FormatError& e) {
      raise (format, e.what ());
    }
    catch (const IoError& e) {
      raise (io, e.what ());
    }
    catch (const NumericalError& e) {
      raise (numerical, e.what ());
    }
    catch (const Error& e) {
      raise (error, e.what ());
    }
  });
}

} // namespace python
} // namespace morphreg
