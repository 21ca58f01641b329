#version 450
// Each active key's artwork (premultiplied alpha, one layer per key) sampled at its UVs and
// blended by the interpolation weights; keys with zero weight are not sampled.
#extension GL_GOOGLE_include_directive : require
#include "artwork_push.glsl"

// Built three times, MAX_ACTIVE = 2, 4 and 8 (shaders/CMakeLists.txt): fewer interpolated UVs per
// fragment when fewer keys are in play (about 1.4x faster on lavapipe for two keys than eight).

layout(set = 0, binding = 0) uniform sampler2DArray artwork;
layout(location = 0) in vec2 uv[MAX_ACTIVE];
layout(location = 0) out vec4 color;  // premultiplied; blended ONE, ONE_MINUS_SRC_ALPHA

void main() {
  vec4 sum = vec4(0.0);
  for (int k = 0; k < MAX_ACTIVE; ++k) {
    if (k >= draw.activeCount) break;
    sum += activeWeight(k) * texture(artwork, vec3(uv[k], float(activeLayer(k))));
  }
  color = sum * draw.tint;
}
