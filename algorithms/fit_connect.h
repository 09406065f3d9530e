// FitConnect (Ohrhallinger, Wimmer 2018, "FitConnect: Connecting Noisy 2D Samples by
// Fitted Neighbourhoods", Computer Graphics Forum 37(1); survey, "Noisy Points Fitting"
// and "Robustness to Noise"): every point grows its neighbourhood, nearest first, until a
// circle fitted to it "conforms" (p lies between its two extreme neighbours along the fit);
// two points whose fitted neighbourhoods hold each other on facing sides ("overlap")
// become curve neighbours, and the points between them that both neighbourhoods hold are
// redundant and dropped. A thick noisy band so thins to one chain of representative points.
//
// Output: the representative points only (the manifold, leaf and sharp points), each moved
// to the mean of its projections onto the fits that hold it (the authors' blending), with
// edges between them; every other input point is dropped, as in the authors' program. On
// a noise-free sampling nearly all points stay representatives, blended by at most the
// fits' residuals; on their fish.txt (1000 points in a noisy band) 48 remain (theirs: 46).
// Cost: a neighbourhood refits at every growth, so a noisy band whose neighbourhoods grow to
// K points costs O(n K) fits of O(K); measured 96 ms on fish.txt (theirs 3.4 s), 4.6 s on
// 10^4 lfs-noisy points at delta 0.1 (theirs 809 s; K grows with the density, so about
// n^2), 446 s on 10^5, 29 ms on 10^4 noise-free ones (theirs 4.9 s). Where the band keeps
// its density as n grows (K fixed), n log n: 35 ms, 0.41 s and 5.1 s at 10^3, 10^4 and 10^5
// points (noisy_reconstruction_benchmark, noisy_band).
//
// The state machine is the authors' (stefango74/fitconnect, Reconstruct2D.cpp,
// reconstructNoisy with SHARPLEAF; StretchDenoise's repository has the same pass), read and
// re-expressed here; nothing is copied. Where ours differs, and why:
//   - Fits. Both order each neighbourhood around Al-Sharadqah and Chernov's hyper circle
//     fit. Its centre solves a quartic, so ours computes it in double (in units of a power
//     of two about p, so that it commutes with scaling by powers of two) and then takes it
//     as a given point: the order along the fit and the conforming test are exact signs of
//     polynomials in the input coordinates and that centre (geometry/exact_sign.h), as
//     CGAL's Exact_predicates_inexact_constructions_kernel treats a construction. Where the
//     hyper fit degenerates (nearly collinear members) ours uses Kasa's fit, whose centre
//     is rational, and orders exactly collinear members along their line; theirs, below an
//     absolute threshold, takes an ad hoc centre off the first two members' chord. Ours
//     before 2026-12-05 used Kasa's fit throughout: its shape differed from theirs on 4 of
//     their 24 files and it cut the corners of their stairs; their program with Kasa's fit
//     put in did the same. Now 23 of 24 shapes are theirs (family.p2d: cocircular grid
//     squares, whose order along a fit hangs on how its centre is rounded).
//   - Nearest neighbours come from exact distances with ties to the smaller index (theirs:
//     ANN in double, ties in its tree order), and a neighbourhood stops growing at
//     `max_neighbors` points (theirs at the whole point set). The bound keeps the run
//     O(n K^2 log K) on adversarial input. On the authors' fish.txt neighbourhoods grow to
//     874 points (with Kasa's fit), and a bound of 128 left 10 pieces instead of one curve: hence 1024.
//   - Sharp corners. Theirs joins two curve ends at a non-conforming point when the ends'
//     outward edges cross the neighbourhood's circle within 60 degrees of each other, as
//     seen from the point (float constructions). Ours compares the angle at the point
//     between the ends' outward neighbours themselves, exactly, against `sharp_angle`;
//     and an edge parallel to the joint does not block it unless they touch (theirs counts
//     every parallel edge as crossing).
//   - Guards where their code relies on assertions or reads index -1 (a link slot taken
//     twice, a link to a missing point): such a step is skipped here, and an edge is
//     output only where both points link to each other (theirs: where either does). A visit cap
//     (8 n max_neighbors) guards against a cycle of state changes; none was seen.
//   - Blending. Theirs intersects the point's own normal line with each fit; ours projects
//     the point radially onto the fit (its nearest point on it). Both keep only
//     projections inside the fitted arc, and sharp points and their neighbours unmoved.
//     Theirs fits each manifold point's own neighbourhood; on a sparse noisy sampling that
//     is 3 to 5 points, which barely smooth. Ours widens the window by the neighbourhoods of
//     up to `smoothing` (2) representatives on each side, while the fit's residual stays
//     that of noise (it at most doubles per step), and only as far as the input's noise
//     level asks: the median, over the representatives, of a one-hop window's fit residual
//     against the squared edge length; above 0.005 one hop, above 0.03 `smoothing` (chosen
//     on the noisy-full and lfsnoise-full suites, 200 curves per level, so not validated on
//     other curves). There, against their window (`smoothing` = 0): RMS distance 0.0277
//     instead of 0.0354 of the diagonal at lfs noise 0.5 and 0.0081 instead of 0.0100 at
//     uniform noise 0.03, the same 0.0035 without noise (always two hops: 0.0046).
// Ties: neighbours at equal distance by index; along a fit, points at the same angle by
// index; a point on the ray from the fit centre through p counts as after p.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "algorithms/algorithm.h"

namespace curvebench::algorithms {

// FitConnect's settings; the registry exposes each as a parameter of the same name.
struct Fit_connect_options {
  int max_neighbors = 1024;  // the largest neighbourhood a point grows to (2 to 65536)
  double sharp_angle = 60;   // degrees: curve ends meeting within it form a sharp corner
  int smoothing = 2;         // representatives on each side a blending fit may take in under heavy
                             // noise (0 to 64); under light noise at most 1, without noise none
  bool blend = true;         // output points blended onto the fits (else input positions)
};

// The connectivity pass alone, on input indices: the representative points (increasing)
// and the edges between them (canonical), at most two per point.
struct Fitted_connectivity {
  std::vector<std::uint32_t> representatives;  // input indices, increasing
  std::vector<Edge> edges;                     // between input indices, canonical
};

// Both throw std::invalid_argument for equal points, a non-finite coordinate or bad options.
Fitted_connectivity fit_connect_connectivity(std::span<const Point> points, const Fit_connect_options& options = {});
// `points` of the result: the representatives (blended), in input order; edges index them.
Reconstruction fit_connect_reconstruction(std::span<const Point> points, const Fit_connect_options& options = {});
// The registry's entry "fit-connect", with parameters max_neighbors, sharp_angle, smoothing
// and blend (Fit_connect_options).
Algorithm fit_connect_algorithm();

}  // namespace curvebench::algorithms
