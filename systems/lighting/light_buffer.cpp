#include "systems/lighting/light_buffer.h"

#include <epoxy/gl.h>

#include <cstring>

#include "systems/lighting/light_block.h"

namespace pyro {

LightBuffer::LightBuffer(const LightBlock& block) : buffer_(gpu::make_buffer()), block_(block) {
  glNamedBufferData(buffer_.get(), sizeof(LightBlock), &block_, GL_DYNAMIC_DRAW);
}

void LightBuffer::upload(const LightBlock& block) {
  if (std::memcmp(&block, &block_, sizeof(LightBlock)) == 0) return;
  block_ = block;
  glNamedBufferSubData(buffer_.get(), 0, sizeof(LightBlock), &block_);
}

void LightBuffer::bind() const { glBindBufferBase(GL_UNIFORM_BUFFER, kLightBlockBinding, buffer_.get()); }

namespace {

LightBlock frame_block(ecs::World& world) {
  const LightBlock* block = world.try_resource<const LightBlock>();
  return block ? *block : gather_light_block(world);
}

}  // namespace

ecs::SystemDesc light_upload_system() {
  return {.name = "light_upload",
          .phase = ecs::Phase::render,
          .access = ecs::Access::of<ecs::Reads<LightBlock, SceneLighting, FireLights>, ecs::Writes<LightBuffer>>(),
          .run = [](ecs::World& world) { world.resource<LightBuffer>().upload(frame_block(world)); },
          .setup =
              [](ecs::World& world) {
                if (!world.has_resource<LightBuffer>()) world.set_resource<LightBuffer>(frame_block(world));
              },
          .main_thread = true};
}

}  // namespace pyro
