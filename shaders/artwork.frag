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
//
// Keys are the drawings: layers 0..m-1 hold the drawings with their rim along the mesh boundary
// made opaque (render::silhouetteArtwork: the mesh's edge is the silhouette), layers m..2m-1 the
// drawings as drawn. At and near a key (keyness > 0, render::keyness) the drawn layers are mixed in,
// and the keys' rims outside the mesh (render::KeyRim, drawn after the mesh where it drew nothing)
// carry the drawn antialiased edge, so that at w = e_i the frame is key i's drawing.
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
  vec4 drawn = vec4(0.0);
  float opaquest = 0.0;
  for (int k = 0; k < MAX_ACTIVE; ++k) {
    if (k >= draw.activeCount) break;
    // Beyond the texture the drawing has nothing (the sampler clamps to its edge texels, which a
    // shape touching the canvas's edge draws opaque): the rim reaches up to its width past it.
    const bool beyond = draw.rim != 0 && (any(lessThan(uv[k], vec2(0.0))) || any(greaterThan(uv[k], vec2(1.0))));
    if (draw.keyness > 0.0 && !beyond)
      drawn += activeWeight(k) * texture(artwork, vec3(uv[k], float(activeLayer(k) + draw.keyCount)));
    if (draw.rim != 0) continue;
    vec4 texel = texture(artwork, vec3(uv[k], float(activeLayer(k))));
    sum += activeWeight(k) * texel;
    opaquest = max(opaquest, texel.a);
  }
  if (draw.rim != 0) {
    color = draw.keyness * drawn * draw.tint;
    return;
  }
  if (seam > 0.0 && sum.a > 0.0) sum *= mix(sum.a, opaquest, seam) / sum.a;
  sum = mix(sum, drawn, draw.keyness);
  // An opened cut's edge drawn with the drawing's outline ink: a band of the line's width along the
  // side (distance interpolated across the triangles that touch it, exact on a straight side),
  // antialiased over a pixel, over the artwork where the shape is.
  float cover = ink.z * clamp(ink.y - ink.x + 0.5, 0.0, 1.0);
  sum = mix(sum, vec4(inkColour * sum.a, sum.a), cover);
  color = sum * draw.tint;
}
