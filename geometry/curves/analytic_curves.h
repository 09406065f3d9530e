// Smooth closed curves given by formulas: the survey's smooth curve C ("Definitions and
// Notations": twice differentiable, so lfs > 0 and epsilon-samplings exist) in shapes
// whose length, curvature and medial axis are known or easy to check, plus random smooth
// curves for certifying sampling theorems on many cases.
//
// Each curve is one closed component of one piece with analytic derivatives, traversed
// counterclockwise from its point on the positive x axis (a random Fourier curve: from
// its point at angle 0). The exception is a superellipse with exponent n < 2: it is not
// twice differentiable at its four axis points, which become the joins of four pieces
// (see superellipse()).
#pragma once

#include <cstdint>

#include "geometry/curves/curve.h"

namespace curvebench::geometry {

// Name "circle:r=R". Throws std::invalid_argument unless r > 0 and finite.
Curve circle(double r);

// x = a cos θ, y = b sin θ. Name "ellipse:a=A,b=B". Throws unless a, b > 0 and finite.
Curve ellipse(double a, double b);

// |x/a|^n + |y/b|^n = 1, n > 0, in the polar form r(φ) = (|cos φ/a|^n + |sin φ/b|^n)^(-1/n).
// n >= 2: one twice-differentiable piece. 1 < n < 2: four quadrant pieces in the same
// form; the curve is C1 and its curvature is unbounded at the axis points. n <= 1: four
// quadrant pieces (1-u)^(1/n) A + u^(1/n) B between the axis points A and B, regular at
// both ends, so the axis points are corners (n = 1, a rhombus) or cusps (n < 1) that
// Curve_component::corners() reports. Name "superellipse:a=A,b=B,n=N".
Curve superellipse(double a, double b, double exponent);

// The random part of a random Fourier curve: how many harmonics perturb the unit circle,
// and how strongly. Part of the curve's name, so a name makes the same curve again.
struct Fourier_curve_parameters {
  int harmonics = 5;       // perturbing harmonics k = 2 .. harmonics + 1
  double amplitude = 0.4;  // coefficient of harmonic k drawn uniformly from [-1, 1) * amplitude / k^decay
  double decay = 2;        // the exponent of k above: higher harmonics are weaker; >= 0
};

// (x, y)(θ) = (cos θ, sin θ) + Σ_k (A_k cos kθ + B_k sin kθ) with random vectors A_k, B_k:
// a smooth closed curve, re-drawn (attempt i uses a seed derived from seed and i) until it
// is simple: regular, its tangent turning once round (no small loop), and its polyline of
// 8192 equal parameter steps free of self-intersections by exact segment predicates. The coefficients come from std::mt19937_64 through a fixed
// 53-bit mapping, so they are bit-identical on every platform. Name
// "fourier:seed=S,harmonics=H,amplitude=A,decay=D". Throws std::invalid_argument for
// harmonics outside [0, 64], a negative or non-finite amplitude or decay, or if 1000
// attempts all fail (amplitude far too large).
Curve random_fourier_curve(std::uint64_t seed, const Fourier_curve_parameters& parameters = {});

// The default `separation` of random_fourier_curves(), in the curves' units (the unit
// circle that each component perturbs is 2 across).
inline constexpr double component_gap = 1.5;
// Several components for multi-curve experiments: random_fourier_curve(seed + c, parameters)
// for c = 0 .. components - 1, in a row along x, `separation` apart beyond their bounding
// boxes (the default, component_gap, is wide against every component's features, so each
// keeps its own lfs near it; a small separation makes the gap set lfs there: at most
// separation / 2 where two components face each other). One component is
// random_fourier_curve itself; otherwise the name ends in ",components=K" and, unless the
// separation is the default, ",separation=D". Throws std::invalid_argument for components
// outside [1, 64] or a separation that is not positive and finite.
Curve random_fourier_curves(std::uint64_t seed, const Fourier_curve_parameters& parameters, int components,
                            double separation = component_gap);

// The survey's open curves ("Open Curves": "samples missing from an object boundary"):
// random_fourier_curve(seed, parameters) with the fraction `gap` of its parameter range
// removed, centred opposite its start. A small gap is a closed curve with a hole in its
// sampling; a gap near 1/2 is an arc. One open component. Name "fourier:...,gap=G".
// Throws std::invalid_argument unless 0 < gap < 1.
Curve random_fourier_arc(std::uint64_t seed, const Fourier_curve_parameters& parameters, double gap);

// A hole: random_fourier_curve(seed) and, inside it, another random Fourier curve scaled
// about the origin so that the two are `separation` apart (the smallest distance between
// dense polylines of both, within 1e-3 of it; lfs is at most separation / 2 where they
// face each other). The inner curve is re-drawn while its scaled copy would cross the
// outer one (exact predicates). Two closed components, outer first. Name
// "nested:seed=S,separation=D". Throws std::invalid_argument for a separation that is not
// positive and finite, or too wide for the outer curve.
Curve nested_fourier_curves(std::uint64_t seed, double separation);

// An open Archimedean spiral r(θ) growing linearly from `inner` to 1 over `turns` turns,
// turns in [1, 2.5) and inner in [0.15, 0.4) drawn from the seed, as is the starting
// angle. One open component. Name "spiral:seed=S".
Curve random_spiral(std::uint64_t seed);

// A smooth closed curve that crosses itself transversally (survey, "Curves with
// Self-Intersections"): the Lissajous figure (w sin(aθ + φ), sin(bθ)) with the phase φ and
// width w in [1, 1.5) drawn from the seed, plus small random harmonics 1..4 (0.04 / k).
// For coprime a < b and a generic phase it crosses itself lissajous_crossings(a, b) times;
// draws are repeated until it does, every crossing at 20° or more and the crossings 0.05 or
// more apart (curve_crossings on 8192 chords). Name "lissajous:a=A,b=B,seed=S". Throws
// std::invalid_argument unless a and b are coprime, 1 <= a < b <= 5 (4:5 crosses 31 times),
// or if 200 draws all fail.
Curve lissajous_curve(int a, int b, std::uint64_t seed);
// 2ab - a - b: how many times the Lissajous figure of coprime a < b crosses itself at a
// generic phase, and so how many crossings lissajous_curve(a, b, seed) has.
constexpr int lissajous_crossings(int a, int b) { return 2 * a * b - a - b; }

}  // namespace curvebench::geometry
