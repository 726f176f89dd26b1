// Fewer transfer-function nodes at a stated error. Every node is a cut of every ray segment the
// mappers integrate exactly, so a frame's cost grows with the nodes a segment crosses: a sampled
// colour map (ParaView's presets have 256 nodes) costs several times a hand-made ramp. Most of those
// nodes lie within display precision of the straight line between their neighbours; dropping them
// leaves the function's shape and makes the cost follow its curvature instead of its sampling.
//
// The kept nodes are a subset of the given ones, and a dropped node's colour is within
// `colorTolerance` (each channel) of the line between the kept nodes around it and its extinction
// within `extinctionTolerance` times its own. Both functions are linear between the given nodes, so
// the bound at the nodes holds at every scalar: colour within the tolerance everywhere, and extinction
// within the relative tolerance everywhere, so any ray's optical depth too (zero extinction stays
// exactly zero). VTK-free.
#ifndef uvTransferFunctionSimplification_h
#define uvTransferFunctionSimplification_h

#include "uvOpticalModel.h"

#include <cmath>
#include <cstddef>
#include <vector>

namespace uv
{

/// Whether every node strictly between `first` and `last` is within the tolerances of the straight
/// line from node `first` to node `last` (false where two of them share a scalar: a step).
inline bool NodesBetweenWithin(const std::vector<TransferFunction::Node>& nodes, std::size_t first, std::size_t last,
  double colorTolerance, double extinctionTolerance)
{
  const TransferFunction::Node& a = nodes[first];
  const TransferFunction::Node& b = nodes[last];
  const double span = b.Scalar - a.Scalar;
  if (!(span > 0.0))
    return false;
  for (std::size_t k = first + 1; k < last; ++k)
  {
    const TransferFunction::Node& node = nodes[k];
    if (!(node.Scalar > a.Scalar && node.Scalar < b.Scalar))
      return false;
    const double t = (node.Scalar - a.Scalar) / span;
    const glm::dvec3 color = a.Color + t * (b.Color - a.Color);
    for (int channel = 0; channel < 3; ++channel)
      if (!(std::abs(color[channel] - node.Color[channel]) <= colorTolerance))
        return false;
    const double extinction = a.Extinction + t * (b.Extinction - a.Extinction);
    if (!(std::abs(extinction - node.Extinction) <= extinctionTolerance * node.Extinction))
      return false;
  }
  return true;
}

/// The nodes (sorted by scalar) with those dropped that the tolerances allow: from each kept node,
/// the next kept one is the farthest whose line covers every node in between. Keeps the first and
/// last nodes, and both nodes of every step. Tolerances of zero drop only exactly collinear nodes.
inline std::vector<TransferFunction::Node> SimplifyTransferFunction(
  const std::vector<TransferFunction::Node>& nodes, double colorTolerance, double extinctionTolerance)
{
  if (nodes.size() < 3)
    return nodes;
  std::vector<TransferFunction::Node> kept{ nodes.front() };
  std::size_t from = 0;
  while (from + 1 < nodes.size())
  {
    std::size_t to = from + 1;
    while (to + 1 < nodes.size() && NodesBetweenWithin(nodes, from, to + 1, colorTolerance, extinctionTolerance))
      ++to;
    kept.push_back(nodes[to]);
    from = to;
  }
  return kept;
}

} // namespace uv

#endif
