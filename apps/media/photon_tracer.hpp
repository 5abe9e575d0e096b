#pragma once
// The photon pass of a scene (Jensen style; paper section 2): photons leave the point light uniformly
// (or the directional disk light, see emit_photon),
// fly by transmittance sampling in the medium they are in, reflect or refract at the dielectric
// boundary by Russian roulette on the Fresnel reflectance (total internal reflection included), and are
// stored at every medium interaction before the albedo roulette [A4], in the inside or outside map.
#include <cstdint>
#include <vector>

#include "apps/media/media_scene.hpp"
#include "apps/common/media/photon_map.hpp"

namespace gcsim::media {

struct PhotonPassResult {
  std::vector<Photon> outside, inside;
  std::uint64_t flights = 0, surface_events = 0, escaped = 0, absorbed = 0, capped = 0;
  std::uint64_t entered = 0;  // crossings of the boundary from outside to inside
  BoundaryTally boundary;     // a mesh object's tree nodes and triangles tested
};

// Traces photons [first, last) of the scene's photons_emitted; photon i uses its own random stream
// (seed, i), so any split of the range over nodes gives the same photons. jobs > 1: batches of the
// range on that many host threads, joined in photon order (the same result byte for byte).
PhotonPassResult trace_photons(const MediaScene& scene, std::size_t first, std::size_t last, int jobs = 1);
inline constexpr std::size_t kPhotonBatchesPerThread = 4;  // batches per host thread, for balance

}  // namespace gcsim::media
