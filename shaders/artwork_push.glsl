// Push constants of the artwork pipeline (std430, 112 bytes), shared by its two stages. Matches
// ArtworkPush in engine/mesh_renderer.cpp.
layout(push_constant) uniform ArtworkPush {
  vec4 view;         // clip = position * view.xy + view.zw (positions in drawing pixels)
  vec4 tint;         // multiplies the premultiplied colour: (1,1,1,1) plain; onion skins fade it
  vec4 weights[2];   // weights of the active keys (up to 8), summing to 1
  ivec4 layers[2];   // their texture layers, which are their key indices
  int activeCount;   // how many keys are active (weight > 0), 0..8
  int keyCount;      // keys in the multimesh: UVs are stored vertex-major, keyCount per vertex
  float keyness;     // 0..1: how much the keys' own drawings show (layers keyCount..2 keyCount-1)
  int rim;           // 1 while drawing the keys' rims outside the mesh (render::KeyRim), 0 for the mesh
} draw;

float activeWeight(int k) { return draw.weights[k >> 2][k & 3]; }
int activeLayer(int k) { return draw.layers[k >> 2][k & 3]; }
