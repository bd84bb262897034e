#version 450 core
// The GPU draw order's first step (systems/gpu_sorting/gpu_depth_sort.h): each particle's sort
// key, and culling. A particle whose bounding sphere (u_cull_radii radii) lies outside every
// frustum of u_planes is left out; the others are appended, in any order, as
// uvec4(descending depth bits, set rank << u_id_bits | id, particle, 0). The key is a strict total
// order, so the sort's result does not depend on the order of appending.
// Every float operation is `precise` and written in the CPU's order (systems/sorting/
// depth_sort.cpp's write_keys, engine/math/view_frustum.cpp's mark_spheres_in_any), so that the
// depths and the culling are the CPU's own, bit for bit.
#include "radix_sort.glsl"

layout(local_size_x = 256) in;

#define MAX_VIEWS 8

layout(std430, binding = 0) readonly buffer ParticleRecords { vec4 records[]; };
layout(std430, binding = 1) readonly buffer ParticleIds { uint ids[]; };
layout(std430, binding = 2) readonly buffer SetStarts { uint set_starts[]; };  // sets + 1 entries
layout(std430, binding = 4) writeonly buffer Elements { uvec4 elements[]; };

uniform uint u_particles;
uniform uint u_sets;
uniform uint u_id_bits;
uniform vec3 u_eye;
uniform vec3 u_forward;
uniform int u_by_eye_distance;
uniform int u_views;
uniform vec4 u_planes[6 * MAX_VIEWS];
uniform float u_cull_radii;

// radix_sort.h's descending_depth_bits: an unsigned integer that orders like the depth, farther
// first (-0 taken as +0).
uint descending_depth_bits(float depth) {
  uint bits = depth == 0.0 ? 0u : floatBitsToUint(depth);
  uint ascending = (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
  return ~ascending;
}

bool seen_by_a_view(vec4 centre_radius) {
  if (u_views == 0) return true;
  precise float reach = -u_cull_radii * centre_radius.w;
  for (int v = 0; v < u_views; ++v) {
    bool inside = true;
    for (int q = 0; q < 6; ++q) {
      vec4 plane = u_planes[6 * v + q];
      precise float distance = plane.x * centre_radius.x + plane.y * centre_radius.y +
                               plane.z * centre_radius.z + plane.w;
      inside = inside && distance >= reach;
    }
    if (inside) return true;
  }
  return false;
}

// The rank of the set particle p belongs to: the last set starting at or before p.
uint set_of(uint p) {
  uint lo = 0u, hi = u_sets - 1u;
  while (lo < hi) {
    uint mid = (lo + hi + 1u) / 2u;
    if (set_starts[mid] <= p) lo = mid; else hi = mid - 1u;
  }
  return lo;
}

void main() {
  uint p = gl_GlobalInvocationID.x;
  if (p >= u_particles) return;
  vec4 centre_radius = records[2u * p];
  if (!seen_by_a_view(centre_radius)) return;
  precise float dx = centre_radius.x - u_eye.x;
  precise float dy = centre_radius.y - u_eye.y;
  precise float dz = centre_radius.z - u_eye.z;
  precise float depth = u_by_eye_distance != 0
                            ? dx * dx + dy * dy + dz * dz
                            : dx * u_forward.x + dy * u_forward.y + dz * u_forward.z;
  uint set = set_of(p);
  uint tie_break = (u_id_bits >= 32u ? 0u : set << u_id_bits) | ids[p];
  uint slot = atomicAdd(kept, 1u);
  elements[slot] = uvec4(descending_depth_bits(depth), tie_break, p, 0u);
}
