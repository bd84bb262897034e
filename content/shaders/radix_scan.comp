#version 450 core
// A radix pass's second step (radix_sort.glsl): the block counts, digit-major, replaced by their
// exclusive prefix sum, so block_counts[digit * blocks + block] becomes where that block's
// elements of that digit begin in the pass's output. One work group; each thread sums a run.
layout(local_size_x = 256) in;

layout(std430, binding = 6) buffer BlockCounts { uint block_counts[]; };

uniform uint u_entries;

shared uint s_sums[256];

void main() {
  uint t = gl_LocalInvocationID.x;
  uint per = (u_entries + 255u) / 256u;
  uint begin = min(t * per, u_entries), end = min(begin + per, u_entries);
  uint sum = 0u;
  for (uint i = begin; i < end; ++i) sum += block_counts[i];
  s_sums[t] = sum;
  barrier();
  // Inclusive scan of the threads' sums (Hillis and Steele).
  for (uint offset = 1u; offset < 256u; offset <<= 1u) {
    uint before = t >= offset ? s_sums[t - offset] : 0u;
    barrier();
    s_sums[t] += before;
    barrier();
  }
  uint running = s_sums[t] - sum;
  for (uint i = begin; i < end; ++i) {
    uint count = block_counts[i];
    block_counts[i] = running;
    running += count;
  }
}
