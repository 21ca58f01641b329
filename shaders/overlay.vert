#version 450
// Overlay lines and marks (wireframe, cohesive edges, features): positions in drawing pixels and a
// premultiplied colour per vertex.
layout(push_constant) uniform OverlayPush {
  vec4 view;  // clip = position * view.xy + view.zw
} draw;

layout(location = 0) in vec2 position;
layout(location = 1) in vec4 colour;
layout(location = 0) out vec4 vertexColour;

void main() {
  vertexColour = colour;
  gl_Position = vec4(position * draw.view.xy + draw.view.zw, 0.0, 1.0);
}
