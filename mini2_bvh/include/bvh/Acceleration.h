#pragma once
/// @file Acceleration.h
/// The acceleration structures a render can ask for by name (a scene file's render.accel, rt's
/// --accel, the benchmarks' rows): one list, so that every place that reads a name knows the
/// same ones.

#include <array>
#include <memory>
#include <span>
#include <string_view>

#include "intersections/Geometries.h"
#include "intersections/Intersectable.h"
#include "lighting/LightSource.h"

namespace rt {

/// "none": the scene's own list (the course's linear search); "cbr": a bounding box around each
/// shape, tested before the shape; "bvh": the bounding volume hierarchy, binary (the course's);
/// "bvh4": the same tree collapsed into nodes of four boxes tested together (WideBvh.h), the
/// default; "grid": the regular grid of voxels walked by 3D-DDA.
inline constexpr std::array<std::string_view, 5> ACCELERATION_NAMES{"none", "cbr", "bvh", "bvh4",
                                                                    "grid"};

/// What a render uses when neither the scene nor the command line names an acceleration.
inline constexpr std::string_view DEFAULT_ACCELERATION = "bvh4";

/// True when name is one of ACCELERATION_NAMES.
bool isAccelerationName(std::string_view name) noexcept;

/// The structure name asks for, built over shapes (which must outlive it); null for "none", where
/// the caller intersects shapes itself.
/// @throws std::invalid_argument naming an unknown name and the known ones.
std::unique_ptr<Intersectable> makeAcceleration(std::string_view name, const Geometries& shapes);

/// What a render intersects: the structure name asks for and, when lightBuffers, a light buffer
/// for each point light of `lights` (lightbuffer/LightBuffers.h) around it, which its shadow rays
/// then take; the image is the same either way, bit for bit. Null only for "none" without light
/// buffers (the caller intersects shapes itself). shapes must outlive the result.
/// @throws std::invalid_argument naming an unknown name and the known ones.
std::unique_ptr<Intersectable> makeAcceleration(std::string_view name, const Geometries& shapes,
                                                std::span<const LightSource> lights,
                                                bool lightBuffers);

}  // namespace rt
