#version 450
// The multimesh at the current positions x (streamed per frame), with every active key's UVs,
// which are that key's positions over its drawing's size.
#extension GL_GOOGLE_include_directive : require
#include "artwork_push.glsl"

// Built three times, MAX_ACTIVE = 2, 4 and 8 (shaders/CMakeLists.txt): fewer interpolated UVs per
// fragment when fewer keys are in play (about 1.4x faster on lavapipe for two keys than eight).

layout(location = 0) in vec2 position;     // drawing pixels, y down
layout(location = 1) in float seamClosure;  // 1 on a glued cut, 0 away from cuts (render::weldCuts)
layout(location = 2) in vec3 inkIn;         // distance to an opened cut's side, line width (target px), alpha
layout(location = 3) in vec3 inkColourIn;   // straight RGB (render::inkFrame)
layout(std430, set = 0, binding = 1) readonly buffer KeyUVs { vec2 keyUV[]; };  // [vertex * keyCount + key]

layout(location = 0) out vec2 uv[MAX_ACTIVE];
layout(location = MAX_ACTIVE) out float seam;
layout(location = MAX_ACTIVE + 1) out vec3 ink;
layout(location = MAX_ACTIVE + 2) out vec3 inkColour;

void main() {
  for (int k = 0; k < MAX_ACTIVE; ++k)
    uv[k] = k < draw.activeCount ? keyUV[gl_VertexIndex * draw.keyCount + activeLayer(k)] : vec2(0.0);
  seam = seamClosure;
  ink = inkIn;
  inkColour = inkColourIn;
  gl_Position = vec4(position * draw.view.xy + draw.view.zw, 0.0, 1.0);
}
