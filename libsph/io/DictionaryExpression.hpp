// #eval in dictionaries: an arithmetic expression evaluated once, as the dictionary is read,
// into a number. Evaluated by muParser (Debian's libmuparser): + - * / ^, parentheses,
// comparisons (< > <= >= == !=) and && ||, the conditional a ? b : c, and the functions sqrt,
// exp, ln, log10, sin, cos, tan, asin, acos, atan, sinh, cosh, tanh, abs, sign, rint, min, max;
// the constant pi. Macros ($H, ${sub/H}) are replaced by their numbers before; see Dictionary.cpp.
//
//     H       0.6;
//     length  #eval "5.366 * $H";
//     r0      #eval "${spacing} / 2";
#pragma once

#include "core/FatalError.hpp"

#include <string>

namespace sph {

// The value of `expression`, finite; a FatalError at `where` for a malformed expression (with
// muParser's reason and position) or a result that is not finite.
double evaluateDictionaryExpression(const std::string& expression, const SourceLocation& where);

}  // namespace sph
