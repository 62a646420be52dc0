#include "io/DictionaryExpression.hpp"

#include <muParser.h>

#include <cmath>
#include <numbers>

namespace sph {

double evaluateDictionaryExpression(const std::string& expression, const SourceLocation& where) {
    // A long expression is shown by its start (muParser refuses more than 20000 characters).
    const std::string shown = "#eval \"" + (expression.size() > 80 ? expression.substr(0, 60) + "..." : expression) + "\"";
    double value = 0.0;
    try {
        mu::Parser parser;
        parser.DefineConst("pi", std::numbers::pi);
        parser.SetExpr(expression);
        value = parser.Eval();
        // muParser reads "1, 2" as two results and returns the last: one value is asked for.
        if (parser.GetNumResults() != 1)
            throw FatalError(where, shown + ": " + std::to_string(parser.GetNumResults()) + " comma-separated values; #eval gives one number");
    } catch (const mu::Parser::exception_type& e) {
        throw FatalError(where, shown + ": " + e.GetMsg());  // muParser's message gives the position, in the macros' numbers
    }
    if (std::isnan(value)) throw FatalError(where, shown + " is not a number (a square root or logarithm of a negative?)");
    if (!std::isfinite(value)) throw FatalError(where, shown + " is infinite (a division by zero?)");
    return value;
}

}  // namespace sph
