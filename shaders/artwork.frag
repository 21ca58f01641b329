#version 450
// Each active key's artwork (premultiplied alpha, one layer per key) sampled at its UVs and
// blended by the interpolation weights; keys with zero weight are not sampled.
#extension GL_GOOGLE_include_directive : require
#include "artwork_push.glsl"

layout(set = 0, binding = 0) uniform sampler2DArray artwork;
layout(location = 0) in vec2 uv[8];
layout(location = 0) out vec4 color;  // premultiplied; blended ONE, ONE_MINUS_SRC_ALPHA

void main() {
  vec4 sum = vec4(0.0);
  for (int k = 0; k < 8; ++k) {
    if (k >= draw.activeCount) break;
    sum += activeWeight(k) * texture(artwork, vec3(uv[k], float(activeLayer(k))));
  }
  color = sum * draw.tint;
}
