// The GPU draw order's radix sort (systems/gpu_sorting/gpu_depth_sort.h): what its three passes
// share. An element is uvec4(key high word, key low word, value, 0); the 64-bit key
// (high << 32 | low) is sorted ascending, least significant digit first, 4 bits a pass. A block
// is RADIX_THREADS threads of RADIX_ITEMS consecutive elements each; elements at or past the
// command's instance count (the particles the culling kept) take no part.
#define RADIX_BITS 4u
#define RADIX_BUCKETS 16u
#define RADIX_THREADS 256u
#define RADIX_ITEMS 16u
#define RADIX_BLOCK (RADIX_THREADS * RADIX_ITEMS)

// The indirect draw command (glDrawArraysIndirect) whose instance count is the kept particles.
layout(std430, binding = 3) buffer DrawCommand {
  uint vertex_count;
  uint kept;
  uint first_vertex;
  uint base_instance;
};

uint radix_digit(uvec4 element, uint shift) {
  return shift < 32u ? (element.y >> shift) & (RADIX_BUCKETS - 1u)
                     : (element.x >> (shift - 32u)) & (RADIX_BUCKETS - 1u);
}
