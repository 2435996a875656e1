#pragma once
// What the renderer's structures cost in resident memory, per element: the constants of the
// memory estimate (scenes/builder/memory_estimate.h, docs/PERFORMANCE.md "Memory budget").
// Embree's figures are measured by bench/memory_bench.cpp (Embree 3.13, a million elements
// of each: its copies of the buffers plus the BVH built over them); rerun it after an Embree
// upgrade.
#include <cstddef>

namespace landsim::renderer::memory {

// Triangles, indexed, with a normal per vertex: a regular grid (the ground) and a tree's
// tubes and leaves (spatial splits duplicate more of their references; 116 to 123 bytes on
// the aspen, the black oak and the tupelo).
inline constexpr double kEmbreeGridTriangle = 97.0;
inline constexpr double kEmbreeTreeTriangle = 120.0;
inline constexpr double kEmbreeCurveSegment = 59.0;  // round linear curve, FLOAT4 points
inline constexpr double kEmbreeDisc = 66.0;          // oriented disc point, with its normal
inline constexpr double kEmbreeInstance = 353.0;     // geometry object, transform, BVH leaf
// The renderer's own record of a top-level entry (what it is, which level) and of an
// instance's level blend.
inline constexpr double kTopLevelRecord = 12.0 + 24.0;
// A film pixel: colour, depth, normal, albedo, five id planes, coverage, position, the
// luminance variance and the samples taken (21 four-byte values, 84 bytes), and the copies
// the EXR writer and the preview hold while writing (measured 70 bytes in all at the peak of
// a 3840 x 2160 render before coverage, position, variance and samples; their 24 bytes are
// counted, not measured).
inline constexpr double kFilmPixel = 94.0;
// Each sensor band adds a four-byte plane (written to the EXR from the film itself).
inline constexpr double kFilmBandPixel = 4.0;
// The image module's libraries (OpenImageIO, OpenColorIO and theirs), resident once loaded:
// a render loads it before its estimate; `landsim info` counts it without loading it.
inline constexpr double kImageModule = 123e6;

}  // namespace landsim::renderer::memory
