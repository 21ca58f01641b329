#version 450
// The multimesh at the current positions x (streamed per frame), with every active key's UVs,
// which are that key's positions over its drawing's size.
#extension GL_GOOGLE_include_directive : require
#include "artwork_push.glsl"

layout(location = 0) in vec2 position;  // drawing pixels, y down
layout(std430, set = 0, binding = 1) readonly buffer KeyUVs { vec2 keyUV[]; };  // [vertex * keyCount + key]

layout(location = 0) out vec2 uv[8];

void main() {
  for (int k = 0; k < 8; ++k)
    uv[k] = k < draw.activeCount ? keyUV[gl_VertexIndex * draw.keyCount + activeLayer(k)] : vec2(0.0);
  gl_Position = vec4(position * draw.view.xy + draw.view.zw, 0.0, 1.0);
}
