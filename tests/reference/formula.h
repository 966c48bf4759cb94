// The slide's notation, evaluated: a formula as the handout writes it ("-ks (l - l0) e",
// "b (T - T_air) (0, 1)", "-ks (e eᵀ + (1 - l0/l) (I - e eᵀ))") with its symbols bound to
// numbers, vectors or matrices. Takes the text and the bindings; gives the value (a 1x1 matrix
// for a number), or throws std::invalid_argument naming what it cannot read.
//
// Written: numbers, symbols ([A-Za-z][A-Za-z0-9_]*), + - * /, a product by juxtaposition (a
// number times anything, or a matrix product: e eᵀ), · (dot), |x| (a number's absolute value,
// a vector's length), x² (a number squared, a vector's squared length), xᵀ, (a, b) (a vector),
// and an update, "v += f / m dt": the symbol's value plus the change.
#pragma once

#include <Eigen/Dense>
#include <map>
#include <string>

namespace a6::test {

using Value = Eigen::MatrixXd;
using Bindings = std::map<std::string, Value>;

Value evaluateFormula(const std::string& text, const Bindings& bindings);

/// A number as a value.
inline Value scalar(double x) { return Value::Constant(1, 1, x); }

/// The text without its blanks, for finding a formula in prose: "-ks ( e eᵀ )" -> "-ks(eeᵀ)".
std::string withoutBlanks(const std::string& text);

}  // namespace a6::test
