#version 450 core
// A radix pass's first step (radix_sort.glsl): how many of each block's elements have each
// digit, into block_counts[digit * blocks + block].
#include "radix_sort.glsl"

layout(local_size_x = 256) in;

layout(std430, binding = 4) readonly buffer Elements { uvec4 elements[]; };
layout(std430, binding = 6) writeonly buffer BlockCounts { uint block_counts[]; };

uniform uint u_shift;

shared uint s_counts[RADIX_BUCKETS];

void main() {
  uint t = gl_LocalInvocationID.x;
  if (t < RADIX_BUCKETS) s_counts[t] = 0u;
  barrier();
  uint first = gl_WorkGroupID.x * RADIX_BLOCK + t * RADIX_ITEMS;
  uint end = min(first + RADIX_ITEMS, kept);
  for (uint i = first; i < end; ++i) atomicAdd(s_counts[radix_digit(elements[i], u_shift)], 1u);
  barrier();
  if (t < RADIX_BUCKETS) block_counts[t * gl_NumWorkGroups.x + gl_WorkGroupID.x] = s_counts[t];
}
