#version 450
// Each active key's artwork (premultiplied alpha, one layer per key) sampled at its UVs and
// blended by the interpolation weights; keys with zero weight are not sampled.
//
// Across a glued cut (seam = 1) the opacity is the largest of the keys' instead of their weighted
// mean: a key that draws the cut open has antialiased, partly transparent texels along it, and
// averaging them in would show a hairline where the shape is whole. The colour stays the keys'
// colours weighted by w_k alpha_k. Away from cuts (seam = 0) this is the plain weighted blend.
// seam is 1 over the triangles along a glued cut and falls to 0 across the next ring of
// triangles (render::weldCuts), so the opacity returns continuously to the plain blend.
#extension GL_GOOGLE_include_directive : require
#include "artwork_push.glsl"

// Built three times, MAX_ACTIVE = 2, 4 and 8 (shaders/CMakeLists.txt): fewer interpolated UVs per
// fragment when fewer keys are in play (about 1.4x faster on lavapipe for two keys than eight).

layout(set = 0, binding = 0) uniform sampler2DArray artwork;
layout(location = 0) in vec2 uv[MAX_ACTIVE];
layout(location = MAX_ACTIVE) in float seam;
layout(location = MAX_ACTIVE + 1) in vec3 ink;        // distance to an opened cut's side, width (target px), alpha
layout(location = MAX_ACTIVE + 2) in vec3 inkColour;  // straight RGB
layout(location = 0) out vec4 color;  // premultiplied; blended ONE, ONE_MINUS_SRC_ALPHA

void main() {
  vec4 sum = vec4(0.0);
  float opaquest = 0.0;
  for (int k = 0; k < MAX_ACTIVE; ++k) {
    if (k >= draw.activeCount) break;
    vec4 texel = texture(artwork, vec3(uv[k], float(activeLayer(k))));
    sum += activeWeight(k) * texel;
    opaquest = max(opaquest, texel.a);
  }
  if (seam > 0.0 && sum.a > 0.0) sum *= mix(sum.a, opaquest, seam) / sum.a;
  // An opened cut's edge drawn with the drawing's outline ink: a band of the line's width along the
  // side (distance interpolated across the triangles that touch it, exact on a straight side),
  // antialiased over a pixel, over the artwork where the shape is.
  float cover = ink.z * clamp(ink.y - ink.x + 0.5, 0.0, 1.0);
  sum = mix(sum, vec4(inkColour * sum.a, sum.a), cover);
  color = sum * draw.tint;
}
