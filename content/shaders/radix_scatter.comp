#version 450 core
// A radix pass's last step (radix_sort.glsl): each element moved to its place by its digit,
// stably. Thread t owns RADIX_ITEMS consecutive elements of its block; its place among the
// block's elements of digit d is the count of d in the threads before it (a scan of the
// block's digit-by-thread counts) plus those before it in its own run, so the order of
// equal digits is kept.
#include "radix_sort.glsl"

layout(local_size_x = 256) in;

layout(std430, binding = 4) readonly buffer Elements { uvec4 elements[]; };
layout(std430, binding = 5) writeonly buffer Sorted { uvec4 sorted[]; };
layout(std430, binding = 6) readonly buffer BlockCounts { uint block_counts[]; };

uniform uint u_shift;

shared uint s_counts[RADIX_BUCKETS * RADIX_THREADS];  // [digit][thread]
shared uint s_segments[RADIX_THREADS];

void main() {
  uint t = gl_LocalInvocationID.x;
  uint first = gl_WorkGroupID.x * RADIX_BLOCK + t * RADIX_ITEMS;
  uint end = min(first + RADIX_ITEMS, kept);
  for (uint d = 0u; d < RADIX_BUCKETS; ++d) s_counts[d * RADIX_THREADS + t] = 0u;
  for (uint i = first; i < end; ++i) ++s_counts[radix_digit(elements[i], u_shift) * RADIX_THREADS + t];
  barrier();
  // Exclusive scan of each digit's row over the threads: thread t takes row t / 16, segment
  // t % 16 (16 entries).
  uint row = t / 16u, segment = t % 16u, base = row * RADIX_THREADS + segment * 16u;
  uint sum = 0u;
  for (uint k = 0u; k < 16u; ++k) sum += s_counts[base + k];
  s_segments[t] = sum;
  barrier();
  uint running = 0u;
  for (uint k = 0u; k < segment; ++k) running += s_segments[row * 16u + k];
  for (uint k = 0u; k < 16u; ++k) {
    uint count = s_counts[base + k];
    s_counts[base + k] = running;
    running += count;
  }
  barrier();
  for (uint i = first; i < end; ++i) {
    uvec4 element = elements[i];
    uint d = radix_digit(element, u_shift);
    uint place = block_counts[d * gl_NumWorkGroups.x + gl_WorkGroupID.x] + s_counts[d * RADIX_THREADS + t]++;
    sorted[place] = element;
  }
}
