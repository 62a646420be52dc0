// The weight of a pair's kernel gradient in a shifting law's sum, as numbers rather than a type,
// so that the force loop can sum the shifting pairs without an instantiation per law:
//   1 + R (W_ij / W(dx))^n
// Monaghan's tensile (anti-clumping) term: pairs closer than dx push harder. Sun et al.'s PST
// (ShiftingSun2017.hpp) takes R = 0.2, n = 4; Fickian shifting (FickianShiftingLind2012.hpp)
// counts each gradient once, R = 0 and n = 0.
// The pair sums take the two laws' weights as types of their own (chosen per particle, not per
// pair), each giving the general form's values to the bit: with R = 0 the law's sum is the
// concentration gradient's and is not summed (UnitShiftingWeight); Sun's n = 4 squares twice
// without the loop over the exponent's bits (FourthPowerShiftingWeight).
// Reference: J.J. Monaghan, J. Comput. Phys. 159 (2000) 290-311.
#pragma once

namespace sph {

struct TensileShiftingWeight {
    double R = 0.0;
    int n = 0;

    // The power by squaring: n = 4 in two dependent multiplications rather than a chain of four.
    double operator()(double wOverWdx) const {
        double power = 1.0;
        for (int e = n; e > 0; e >>= 1, wOverWdx *= wOverWdx)
            if (e & 1) power *= wOverWdx;
        return 1.0 + R * power;
    }
    bool isOne() const { return R == 0.0; }
};

struct UnitShiftingWeight {};

struct FourthPowerShiftingWeight {
    double R;
    double operator()(double wOverWdx) const {
        const double square = wOverWdx * wOverWdx;
        return 1.0 + R * (square * square);
    }
};

// Calls visit with the weight as its own type: UnitShiftingWeight, FourthPowerShiftingWeight or
// the general one.
template <class Visit>
decltype(auto) withShiftingWeight(const TensileShiftingWeight& weight, Visit&& visit) {
    if (weight.isOne()) return visit(UnitShiftingWeight{});
    if (weight.n == 4) return visit(FourthPowerShiftingWeight{weight.R});
    return visit(weight);
}

}  // namespace sph
