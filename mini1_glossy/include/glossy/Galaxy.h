#pragma once
/// @file Galaxy.h
/// The reference report's final image, "Glassed Galaxy": about a thousand glowing spheres on the
/// spiral arms of a galaxy, floating in a diffused-glass box with a metallic frame on a two-level
/// pedestal, lit by three coloured spot lights. Generated from the reference report's authors'
/// parameters (the course catalogue, §6), with the star count as a parameter so the second mini
/// project can scale it from 10^3 to 10^6 stars.

#include <cstdint>
#include <string>
#include <vector>

#include "camera/CameraSpec.h"
#include "lighting/LitScene.h"

namespace rt {

struct GalaxyParams {
  /// The most arms, positions per arm and stars the generator accepts.
  static constexpr int MAX_ARMS = 1000;
  static constexpr int MAX_PER_ARM = 1'000'000;
  static constexpr long MAX_STARS = 10'000'000;

  int arms = 21;           ///< spiral arms; every seventh from the fourth (4, 11, 18) holds suns
  int perArm = 50;         ///< positions per arm (the reference report's 50)
  long stars = 0;          ///< when > 0: about this many stars, by setting perArm = stars / arms
  bool diffusion = true;   ///< the glass box's beams (the reference report's diffused glass)
  std::uint64_t seed = 1;  ///< the generator's jitter and star colours

  /// @throws std::invalid_argument for arms outside 1..MAX_ARMS, perArm outside 1..MAX_PER_ARM,
  /// stars outside 0..MAX_STARS, naming the parameter, and, when stars is 0, for more than
  /// MAX_STARS positions in all (arms x perArm).
  void validate() const;
  /// The positions per arm these parameters give (perArm, or stars / arms rounded, at least 1).
  int positionsPerArm() const;
};

struct GalaxySetup {
  LitScene scene;
  CameraSpec camera;  ///< the reference report's view: from (100,27,22) at (4,8,4), 1280 x 720
  /// Points of view of the same scene: "main" (the reference report's, the same as camera),
  /// "above", "inside" (through the glass, close to the stars) and "side".
  std::vector<NamedView> views;
};

/*
 * The layout, in the reference report's units (y is up):
 *
 *   floor           the plane y = 0, emission (30,40,70), kD 1
 *   pedestal        two boxes, x∈[−7,19] y∈[2,4] z∈[−7,15] on x∈[−7.5,19.5] y∈[0,2]
 *                   z∈[−7.5,15.5]; brown (80,40,5), kD 0.5 kS 0.35 nSh 10
 *   glass box       x∈[−6.5,18.5] y∈[4,15] z∈[−6.5,14.5]; emission (20,25,25), kD 0.35 kS 0.4
 *                   kT 0.85 kR 0.2 nSh 10; both secondary rays blurred by a beam of N = 10,
 *                   distance 12, radius 0.2 (when diffusion is on)
 *   frame           0.3-wide bars along the glass box's 4 vertical and 4 top edges; dark grey
 *                   (45,30,30), kD 0.5 kS 0.35 kR 0.05 nSh 10
 *   galaxy          arm k (of n), position i (of m): θ = 0.15·i·(49/(m−1)), r = 1.7·e^(0.25θ),
 *                   angle θ + 2πk/n; in the disc's plane (x, z) jitter (U − ½)·0.2·⌊i'/8⌋ with
 *                   i' = 49·i/(m−1), off it (y) U·0.2 − 0.1; the disc tilted 20° about X and
 *                   centred at (4,8,4)
 *     suns          on arms k ≡ 4 (mod 7): 40% orange (255,150,90)·[0.9,1.2), radius
 *                   [0.20,0.23); 50% yellow (255,200,50)·[0.9,1.2), radius [0.16,0.19); 10% none
 *     stars         the other arms: radius 0.05 (scaled by √(50/m)), light blue (80,255,230) or
 *                   near-white (200,250,255), alternately; kD 0.2 kS 0.33 nSh 10
 *     core          radius 1, emission (255,220,110), and a halo of radius 1.3, emission
 *                   (76.5,66,33), kT 0.9 kD 0.1 kS 0.9
 *   lights          spots (kL = kQ = 0.002): teal (0,120,120) at (20,30,4) along (−1.8,−3,0);
 *                   amber (140,100,0) at (0,30,30) along (0,−3,−1.8); purple (120,0,120) at
 *                   (0,30,−20) along (0,−3,1.8)
 *   camera          from (100,27,22) at (4,8,4), up +Y, view plane 384 x 216 at 750, 1280 x 720
 *
 * The reference report's Math.random is replaced by the counter-based RandomStream(seed, arm,
 * position, 0), so a galaxy is a pure function of its parameters.
 */
/// @throws std::invalid_argument for invalid parameters.
GalaxySetup galaxy(const GalaxyParams& params = {});

}  // namespace rt
