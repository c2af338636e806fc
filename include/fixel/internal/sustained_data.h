#pragma once
// J's data in the part's body frame at q* (sustained.cpp builds it,
// sustained_target.cpp answers the jam and escape tests on it), over Q(√d)
// for polyline contacts or certified intervals for curved ones.

#include <array>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "fixel/internal/cone3.h"
#include "fixel/sustained.h"

namespace fixel::internal {

// Everything in the part's body frame at q*, where a finger's push wrench
// (d, (b − c) ⊗ d) is rational: only J's own data lives in NT, exact Q(√d)
// for polyline contacts or certified intervals for curved ones.
template <class NT_>
struct Data {
  using NT = NT_;
  using V = std::array<NT, 3>;
  NT cos, sin;            // the rotation of q*
  std::vector<V> K_rows;  // w ∈ int K ⇔ a·w > 0 for every row (K = −cone(W_n*))
  std::vector<V> K_rays;  // −W_n,i*
  V normaliser;           // Σ K_rows: positive on K \ {0}
  struct Jam {
    std::array<int, 2> fixels;
    std::vector<V> gens;    // −(W_n ± μ W_t) of both fixels
    std::vector<V> facets;  // closed rows: w ∈ jam cone ⇔ a·w ≥ 0 for all
  };
  std::vector<Jam> jams;
  struct Piece {
    std::vector<V> closed, strict, rays;
  };
  std::vector<Piece> pieces;
  bool pieces_decided = true;
};

struct SustainedData {
  std::variant<Data<Q2>, Data<IV>> data;
  // The scene J was built from: a region or J′ asked of a scene that
  // differs where J looks is refused (check_built_from). Null for the
  // design's internal J: not checked.
  std::shared_ptr<const Scene> built_from;
};

// Whether w lies in the closed jam cone.
template <class NT>
bool in_jam(const typename Data<NT>::Jam& jam, const A3<NT>& w) {
  return satisfies(w, jam.facets, {});
}

// J's reason for rejecting a wrench given in frame B at q* (force along
// the part's axes, moment about its centre of mass), "" when it is in J:
// J.why_not of its world-frame form R(θ*)·w_B, without leaving Q(√d).
std::string why_not_in_frame_B(const SustainedSet& J, const VectorQ& w_B);

// InputError naming `field` ("J" or "J'") unless `scene` equals the scene
// the data was built from where J looks: the outline, the centre of mass,
// mass and inertia, and each fixel's point, normal, gap and friction.
void check_built_from(const SustainedData& data, const Scene& scene, const char* field);

inline std::string fixel_name(int i) { return "fixels[" + std::to_string(i) + "]"; }

}  // namespace fixel::internal
