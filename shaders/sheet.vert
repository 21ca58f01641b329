#version 450
// The editor's drawing sheet: one textured rectangle per draw, no vertex buffer. The six vertices
// of two triangles come from gl_VertexIndex; the push constants say where the rectangle lies
// (clip space) and which part of which layer it shows.
#extension GL_GOOGLE_include_directive : require
#include "sheet_push.glsl"

layout(location = 0) out vec2 uv;

void main() {
  const vec2 corners[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));
  vec2 c = corners[gl_VertexIndex];
  uv = mix(sheet.uvRect.xy, sheet.uvRect.zw, c);
  gl_Position = vec4(mix(sheet.clipRect.xy, sheet.clipRect.zw, c), 0.0, 1.0);
}
