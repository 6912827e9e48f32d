#include "signatures.hpp"

#include <cstdlib>
#include <cstring>
#include <regex>
#include <string>
#include <vector>

namespace phongrast::python {
namespace {

namespace py = pybind11;

/// The parameters inside pybind11's "name(a: T, b: U = 1) -> R", split at
/// top-level commas; false when the doc does not start that way.
bool parameters_of(const std::string& doc, const std::string& name, std::vector<std::string>& parameters) {
    if (doc.compare(0, name.size() + 1, name + "(") != 0) return false;
    int depth = 0;
    char quote = 0;
    std::string current;
    for (std::size_t i = name.size() + 1; i < doc.size(); ++i) {
        const char c = doc[i];
        if (quote != 0) {
            if (c == quote) quote = 0;
        } else if (c == '\'' || c == '"') {
            quote = c;
        } else if (c == '(' || c == '[') {
            ++depth;
        } else if (c == ']' || (c == ')' && depth > 0)) {
            --depth;
        } else if (c == ')') {
            if (!current.empty()) parameters.push_back(current);
            return true;
        } else if (c == ',' && depth == 0) {
            parameters.push_back(current);
            current.clear();
            continue;
        }
        current += c;
    }
    return false;
}

std::string trimmed(const std::string& text) {
    const std::size_t begin = text.find_first_not_of(' ');
    const std::size_t end = text.find_last_not_of(' ');
    return begin == std::string::npos ? std::string() : text.substr(begin, end - begin + 1);
}

/// "colors: object = None" -> "colors=None"; a default inspect could not
/// evaluate (an object's repr) becomes "...".
std::string text_parameter(const std::string& parameter) {
    static const std::regex literal(R"(None|True|False|-?[0-9][0-9.e+-]*|'[^']*'|"[^"]*")");
    const std::string text = trimmed(parameter);
    const std::size_t equals = text.find(" = ");
    const std::string head = text.substr(0, equals);
    const std::string name = trimmed(head.substr(0, head.find(':')));
    if (equals == std::string::npos) return name;
    const std::string value = trimmed(text.substr(equals + 3));
    return name + "=" + (std::regex_match(value, literal) ? value : std::string("..."));
}

void add_text_signature(PyObject* function) {
    if (function == nullptr || !PyCFunction_Check(function)) return;
    PyMethodDef* definition = reinterpret_cast<PyCFunctionObject*>(function)->m_ml;
    if (definition == nullptr || definition->ml_doc == nullptr || definition->ml_name == nullptr) return;
    const std::string doc = definition->ml_doc;
    const std::string name = definition->ml_name;
    if (doc.find("\n--\n\n") != std::string::npos) return;  // has one already
    std::vector<std::string> parameters;
    if (!parameters_of(doc, name, parameters)) return;  // overloaded, or not pybind11's format
    std::string signature = name + "(";
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        signature += (i == 0 ? "" : ", ") + text_parameter(parameters[i]);
    }
    signature += ")\n--\n\n" + doc;
    // pybind11 allocated the old doc with strdup and frees ml_doc with free().
    char* replaced = static_cast<char*>(std::malloc(signature.size() + 1));
    if (replaced == nullptr) return;
    std::memcpy(replaced, signature.c_str(), signature.size() + 1);
    definition->ml_doc = replaced;
}

}  // namespace

void add_text_signatures(py::module_& module) {
    for (const auto item : module.attr("__dict__").cast<py::dict>()) {
        PyObject* value = item.second.ptr();
        add_text_signature(value);
        if (!PyType_Check(value)) continue;
        for (const auto member : py::reinterpret_borrow<py::object>(value).attr("__dict__").cast<py::dict>()) {
            PyObject* attribute = member.second.ptr();
            if (PyInstanceMethod_Check(attribute)) {
                add_text_signature(PyInstanceMethod_GET_FUNCTION(attribute));
            } else if (py::isinstance(member.second, py::module_::import("builtins").attr("staticmethod"))) {
                add_text_signature(member.second.attr("__func__").ptr());
            }
        }
    }
}

}  // namespace phongrast::python
