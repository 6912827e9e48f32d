// inspect.signature() for the module's functions and methods.
#ifndef PHONGRAST_PYTHON_SIGNATURES_HPP
#define PHONGRAST_PYTHON_SIGNATURES_HPP

#include <pybind11/pybind11.h>

namespace phongrast::python {

/// Gives every function of `module`, and every method and static method of
/// its classes, a CPython text signature (the "name(params)\n--\n\n" head of
/// a built-in's docstring that inspect.signature() reads), made from the
/// signature line pybind11 wrote: parameter names and simple defaults,
/// without the annotations (those are in phongrast.pyi). Overloaded
/// functions are left alone. Call once, after everything is bound.
void add_text_signatures(pybind11::module_& module);

}  // namespace phongrast::python

#endif  // PHONGRAST_PYTHON_SIGNATURES_HPP
