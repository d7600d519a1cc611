#include "ari_social_sim/rendering/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "ari_social_sim/rendering/floor_shade.hpp"
#include "ari_social_sim/rendering/render_mesh.hpp"
#include "egl_context.hpp"
#include "gl_program.hpp"
#include "lamp_light.hpp"
#include "multisample_target.hpp"

namespace ari_social_sim::rendering {
namespace {

// Shading is deliberately plain, cheap on llvmpipe: outdoors ambient, a sun and a fill light at
// the camera; indoors (a scene with lamps) the ceiling's lamps as the light, with their fall-off,
// a little bounced light and the fill light. The lamps light each vertex (Gouraud shading: the
// room's vertices once, as it is set, the people's every frame), and the floor's contact shadows
// are found per vertex too: looping over lamps and people for every
// pixel cost more than the rest of a frame on llvmpipe. Large surfaces are split into facets
// (RenderPrimitive::max_facet_m) over which their light and shadows hardly change.
const std::string kVertexShader = std::string(R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 colour;
layout(location = 3) in float surface;
layout(location = 4) in float label;
layout(location = 5) in vec3 shape_point;
// The lamps' light, lit once (LampLightBake) for the static meshes, whose lamps and vertices do
// not move; the dynamic mesh's vertices are lit every frame by the lamps nearest the camera.
layout(location = 6) in vec4 baked_lamp_light;
uniform bool lamp_light_baked;
uniform mat4 world_to_optical;
uniform mat4 projection;
out vec3 v_world;
out vec3 v_shape;
out vec3 v_normal;
out vec3 v_colour;
flat out float v_surface;
out float v_depth;
flat out float v_label;
out float v_lamp;
out vec3 v_lamp_direction;
out float v_floor_open;
// Where people stand on the floor, nearest the camera first: x, y and the feet's radius.
uniform int contact_count;
uniform vec3 contacts[16];

)") + kLampLightGlsl + R"(
// Soft contact shadows (ambient occlusion): the floor around someone's feet sees less of the room
// and its lamps, darkest under the feet and fading over a few tenths of a metre.
float floor_occlusion(vec2 p) {
  float open = 1.0;
  for (int i = 0; i < contact_count; ++i) {
    vec2 d = p - contacts[i].xy;
    float r = contacts[i].z;
    open *= 1.0 - 0.55 * exp(-dot(d, d) / (r * r));
  }
  return open;
}

void main() {
  vec4 p = world_to_optical * vec4(position, 1.0);
  vec4 light = baked_lamp_light;
  if (!lamp_light_baked) {
    light = lamp_light(position, normal);
  }
  v_lamp = light.x;
  v_lamp_direction = vec3(0.0, 0.0, 1e-6) + light.yzw;
  v_floor_open = floor_occlusion(position.xy);  // 1 but for the floor (contact_count 0)
  v_world = position;
  v_shape = shape_point;
  v_normal = normal;
  v_colour = colour;
  v_surface = surface;
  v_depth = p.z;
  v_label = label;
  gl_Position = projection * p;
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
in vec3 v_world;
in vec3 v_shape;
in vec3 v_normal;
in vec3 v_colour;
flat in float v_surface;
in float v_depth;
flat in float v_label;
layout(location = 0) out vec4 out_colour;
layout(location = 1) out float out_depth;
layout(location = 2) out float out_label;
uniform vec3 camera_position;
uniform int lamp_count;
in float v_lamp;
in vec3 v_lamp_direction;
in float v_floor_open;
const vec3 sun = normalize(vec3(0.35, 0.55, 1.0));
// Surface codes (rendering::Surface).
const int kFloor = 1;
const int kSkin = 2;
const int kWall = 3;
const int kWood = 4;
const int kCeiling = 5;
const int kLamp = 6;
const int kCloth = 7;

// A pseudo-random value in [0, 1) for a lattice point, by multiplications and fract alone: the
// sine of the usual one-line hash is a polynomial of some forty operations on llvmpipe, and the
// floor's and walls' textures take five to eight hashes a pixel.
float hash(vec2 p) {
  p = fract(p * vec2(0.1307, 0.1173));
  p += dot(p, p.yx + 19.19);
  return fract(p.x * p.y);
}

// Value noise in [0, 1], smooth between the integer lattice's random values.
float value_noise(vec2 p) {
  vec2 cell = floor(p);
  vec2 f = fract(p);
  vec2 w = f * f * (3.0 - 2.0 * f);
  return mix(mix(hash(cell), hash(cell + vec2(1.0, 0.0)), w.x),
             mix(hash(cell + vec2(0.0, 1.0)), hash(cell + vec2(1.0, 1.0)), w.x), w.y);
}

// 0.6 m vinyl tiles, each a little lighter or darker, with 5 mm grout and a fine speckle.
float floor_tiles(vec2 xy) {
  vec2 tile = xy / 0.6;
  vec2 edge = min(fract(tile), 1.0 - fract(tile)) * 0.6;
  float grout = min(edge.x, edge.y) < 0.005 ? 0.85 : 1.0;
  return grout * (0.96 + 0.06 * hash(floor(tile))) * (0.97 + 0.05 * value_noise(xy * 40.0));
}

// Paint with a faint roller texture over a grey skirting board and, to 1 m, the charcoal wall
// protection (dado) of hospital walls, which trolleys and chairs would otherwise scuff. The dado
// gives a frame dark greys that the darkest faces share, so that a global histogram equalisation
// spreads their greys rather than crushing them into the bottom few levels.
float wall_paint(vec3 p) {
  vec2 uv = vec2(p.x + p.y, p.z);
  float skirting = p.z < 0.1 ? 0.55 : (p.z < 1.0 ? 0.40 : 1.0);
  return skirting * (0.96 + 0.04 * value_noise(uv * 5.0) + 0.03 * value_noise(uv * 70.0));
}

// Grain running horizontally.
float wood_grain(vec3 p) {
  return 0.9 + 0.15 * value_noise(vec2((p.x + p.y) * 3.0, p.z * 45.0));
}

// 1 at whole numbers, falling linearly to 0 halfway between them.
float triangle_wave(float x) {
  return abs(fract(x) * 2.0 - 1.0);
}

// Cloth hanging on a limb or the trunk, in the part's own frame (its axis z, metres): drape folds
// along the part, six around it, deepening and fading as they go down; the folds' valleys see less
// of the room's light. No creases across the part: rings of them every 14 cm, a dark line between
// two bright bands, were where the default frontal cascade fired on sleeves and shirts once
// `equalizeHist` or CLAHE had stretched them (docs/detector_study_log.md, "Clothes without
// creases").
// Polynomials and triangle waves, no transcendental function: llvmpipe pays for each on every
// cloth pixel. The folds' cosine of six times the angle around the axis is Chebyshev's T6 of the
// angle's cosine.
float cloth_folds(vec3 p) {
  vec2 around = p.xy * inversesqrt(max(dot(p.xy, p.xy), 1e-8));
  float c2 = around.x * around.x;
  float cos6 = ((32.0 * c2 - 48.0) * c2 + 18.0) * c2 - 1.0;
  float drape = 0.5 + 0.5 * cos6;
  float depth = 0.3 + 0.7 * triangle_wave(1.1 * p.z + 0.3 * around.y);
  return 1.0 - 0.18 * depth * drape * drape;
}

float texture_of(int surface, vec3 world, vec3 shape) {
  if (surface == kFloor) return floor_tiles(world.xy);
  if (surface == kWall) return wall_paint(world);
  if (surface == kWood) return wood_grain(world);
  if (surface == kCloth) return cloth_folds(shape);
  return 1.0;
}

// Indoors: the lamps scaled so that a face 1 m from a lamp's foot and 0.9 m under it (about 0.27
// of a unit emitter) is about as lit as the sun and sky lit it outdoors, plus bounced light and
// the fill light. Skin also reflects at its surface (`specular`, linear light): the lamps'
// highlight, Blinn-Phong from their mean direction with a broad lobe, as panels 0.6 m wide a metre
// or two overhead give, so that foreheads, noses and cheekbones catch it from above; and the sheen
// of the lit room behind the camera, brightest where the skin faces the camera.
float indoor_lighting(int surface, vec3 n, vec3 to_camera, float fill, out float specular) {
  float lamp = 2.4 * v_lamp;
  specular = 0.0;
  if (surface == kSkin) {
    vec3 half_way = normalize(normalize(v_lamp_direction) + to_camera);
    float lamp_highlight = min(lamp, 1.0) * pow(max(dot(n, half_way), 0.0), 6.0);
    specular = 0.1 * lamp_highlight + 0.04 * fill * fill * fill * fill;
  }
  if (surface == kCeiling) {
    return 0.3 + 0.15 * fill;
  }
  return 0.12 + lamp + 0.2 * fill;
}

void main() {
  int surface = int(v_surface + 0.5);
  vec3 c = v_colour * texture_of(surface, v_world, v_shape);
  out_depth = v_depth;
  out_label = v_label;
  if (surface == kLamp) {  // gives light: as bright as the sensor takes
    out_colour = vec4(c, 1.0);
    return;
  }
  // Ambient light, a sun, the ceiling's light from straight above (forehead and brows bright,
  // under them darker, as indoors) and a fill light at the camera, so that surfaces facing the
  // camera stay bright. The ceiling faces away from all of them and is lit by what the room
  // bounces up.
  vec3 n = normalize(v_normal);
  vec3 to_camera = normalize(camera_position - v_world);
  float fill = max(dot(n, to_camera), 0.0);
  float specular;
  float lighting;
  if (lamp_count > 0) {
    lighting = indoor_lighting(surface, n, to_camera, fill, specular);
  } else {
    lighting = surface == kCeiling
                   ? 0.45 + 0.15 * fill
                   : 0.25 + 0.25 * max(dot(n, sun), 0.0) + 0.35 * max(n.z, 0.0) + 0.3 * fill;
    // Skin's colourless highlight of the fill light (Blinn-Phong: light and view coincide).
    specular = surface == kSkin ? 0.22 * pow(fill, 12.0) : 0.0;
  }
  lighting *= v_floor_open;
  // Colours are display (sRGB) values and light adds up linearly: shade in linear terms.
  vec3 shaded = c * pow(lighting, 1.0 / 2.2);
  // Skin's surface reflection adds to its diffuse light in linear terms too, so that the same
  // reflection shows more on dark skin, whose diffuse light is less, as on real faces. It is
  // colourless; with the display's gamma taken as 2, a grey y becomes sqrt(y^2 + specular). One
  // square root on every pixel: a branch for skin alone, with powers of 2.2, cost llvmpipe a
  // seventh of the head camera's frame.
  float grey = dot(shaded, vec3(0.299, 0.587, 0.114));
  shaded += sqrt(grey * grey + specular) - grey;
  out_colour = vec4(min(shaded, vec3(1.0)), 1.0);
}
)";

// Background where nothing is hit: a pale grey-blue, and depth 0 (turned into NaN on readback).
constexpr float kBackground[4] = {0.78f, 0.84f, 0.9f, 1.0f};

// Maps the optical frame (x right, y down, z forward) to clip space so that window pixel
// (u + 0.5, v + 0.5) is pixel (u, v) of the pinhole model, with v = 0 in the first row read back.
Eigen::Matrix4f projection_of(const PinholeModel& m, double near_m, double far_m) {
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = 2.0 * m.fx / m.width;
  p(0, 2) = 2.0 * (m.cx + 0.5) / m.width - 1.0;
  p(1, 1) = 2.0 * m.fy / m.height;
  p(1, 2) = 2.0 * (m.cy + 0.5) / m.height - 1.0;
  p(2, 2) = (far_m + near_m) / (far_m - near_m);
  p(2, 3) = -2.0 * far_m * near_m / (far_m - near_m);
  p(3, 2) = 1.0;
  return p.cast<float>();
}

// A vertex buffer with its attribute layout.
struct GpuMesh {
  GLuint array{0};
  GLuint buffer{0};
  GLuint baked_light{0};
  GLsizei vertex_count{0};

  void create() {
    glGenVertexArrays(1, &array);
    glGenBuffers(1, &buffer);
    glBindVertexArray(array);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    const GLsizei stride = RenderMesh::kFloatsPerVertex * sizeof(float);
    const int offsets[6] = {0, 3, 6, 9, RenderMesh::kLabelOffset, RenderMesh::kShapePointOffset};
    const int sizes[6] = {3, 3, 3, 1, 1, 3};
    for (GLuint i = 0; i < 6; ++i) {
      glEnableVertexAttribArray(i);
      // OpenGL takes a buffer offset as a pointer.
      // NOLINTNEXTLINE(performance-no-int-to-ptr)
      const void* offset = reinterpret_cast<void*>(offsets[i] * sizeof(float));
      glVertexAttribPointer(i, sizes[i], GL_FLOAT, GL_FALSE, stride, offset);
    }
  }
  void upload(const RenderMesh& mesh) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(float)),
                 mesh.vertices.data(), GL_DYNAMIC_DRAW);
    vertex_count = static_cast<GLsizei>(mesh.vertex_count());
  }
  // Gives the vertices a buffer for their lamp light (attribute 6), which LampLightBake fills.
  void add_baked_light() {
    glGenBuffers(1, &baked_light);
    glBindVertexArray(array);
    glBindBuffer(GL_ARRAY_BUFFER, baked_light);
    glEnableVertexAttribArray(6);
    glVertexAttribPointer(6, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
  }
  void draw() const { draw(0, vertex_count); }
  void draw(GLint first, GLsizei count) const {
    if (count > 0) {
      glBindVertexArray(array);
      glDrawArrays(GL_TRIANGLES, first, count);
    }
  }
  void destroy() {
    glDeleteBuffers(1, &buffer);
    glDeleteBuffers(1, &baked_light);  // 0, for meshes without, is ignored
    glDeleteVertexArrays(1, &array);
  }
};

// Off-screen target of one size: RGBA8 colour, R32F optical depth, R32F labels, 32-bit float
// depth buffer.
struct Framebuffer {
  static constexpr int kBuffers = 4;
  GLuint framebuffer{0};
  GLuint renderbuffers[kBuffers]{0, 0, 0, 0};

  void create(int width, int height) {
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glGenRenderbuffers(kBuffers, renderbuffers);
    const GLenum formats[kBuffers] = {GL_RGBA8, GL_R32F, GL_R32F, GL_DEPTH_COMPONENT32F};
    const GLenum attachments[kBuffers] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1,
                                          GL_COLOR_ATTACHMENT2, GL_DEPTH_ATTACHMENT};
    for (int i = 0; i < kBuffers; ++i) {
      glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers[i]);
      glRenderbufferStorage(GL_RENDERBUFFER, formats[i], width, height);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachments[i], GL_RENDERBUFFER, renderbuffers[i]);
    }
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      throw RenderError("framebuffer " + std::to_string(width) + "x" + std::to_string(height) +
                        " is incomplete");
    }
  }
  void destroy() {
    glDeleteRenderbuffers(kBuffers, renderbuffers);
    glDeleteFramebuffers(1, &framebuffer);
  }
};

// Where each labelled figure (a person) touches the floor: the centre of its vertices within
// kFeetHeightM of the floor, and a radius a little beyond the farthest of them.
std::vector<Eigen::Vector3f> floor_contacts(const RenderMesh& mesh) {
  constexpr float kFeetHeightM = 0.12f;
  struct Feet {
    Eigen::Vector2f sum{Eigen::Vector2f::Zero()};
    std::vector<Eigen::Vector2f> points;
  };
  std::map<float, Feet> by_label;
  const std::vector<float>& v = mesh.vertices;
  for (size_t i = 0; i + RenderMesh::kFloatsPerVertex <= v.size();
       i += RenderMesh::kFloatsPerVertex) {
    const float label = v[i + RenderMesh::kLabelOffset];
    if (label > 0.0f && v[i + 2] < kFeetHeightM) {
      Feet& feet = by_label[label];
      feet.points.emplace_back(v[i], v[i + 1]);
      feet.sum += feet.points.back();
    }
  }
  std::vector<Eigen::Vector3f> contacts;
  for (const auto& [label, feet] : by_label) {
    const Eigen::Vector2f centre = feet.sum / static_cast<float>(feet.points.size());
    float reach = 0.0f;
    for (const Eigen::Vector2f& p : feet.points) {
      reach = std::max(reach, (p - centre).norm());
    }
    contacts.emplace_back(centre.x(), centre.y(), std::clamp(reach + 0.1f, 0.2f, 0.5f));
  }
  return contacts;
}

}  // namespace

struct Renderer::Impl {
  EglContext context;
  std::string device_name;
  GLuint program{0};
  GLint world_to_optical_location{-1};
  GLint projection_location{-1};
  GLint camera_position_location{-1};
  GLint lamp_count_location{-1};
  GLint lamps_location{-1};
  GLint lamp_light_baked_location{-1};
  GLint contact_count_location{-1};
  GLint contacts_location{-1};
  // The shader's arrays: the nearest lamps light a view, the farther ones add little; the
  // nearest people's contact shadows are the ones large enough to see.
  static constexpr size_t kMaxLamps = 32;
  static constexpr size_t kMaxContacts = 16;
  std::vector<Eigen::Vector3f> lamps;     // every lamp of the static scene
  std::vector<Eigen::Vector3f> contacts;  // (x, y, radius) of every labelled figure's feet
  GpuMesh static_mesh;
  GpuMesh floor_mesh;  // the static floors: only their vertices look for contact shadows
  GpuMesh dynamic_mesh;
  std::unique_ptr<LampLightBake> bake;
  // One framebuffer per image size: a rig alternates between cameras of different sizes.
  std::map<std::pair<int, int>, Framebuffer> framebuffers;
  std::map<std::tuple<int, int, int>, std::unique_ptr<MultisampleTarget>> multisample_targets;
  cv::Mat label_scratch;  // CV_32FC1, the label attachment as read back

  MultisampleTarget& multisample_target_of(int width, int height, int samples) {
    std::unique_ptr<MultisampleTarget>& target = multisample_targets[{width, height, samples}];
    if (!target) {
      target = std::make_unique<MultisampleTarget>(width, height, samples);
    }
    return *target;
  }

  // Sets a shader array to the `max` points nearest the camera (in the floor plan for contacts,
  // whose z is a radius) and its count uniform to how many there are.
  static void upload_nearest(std::vector<Eigen::Vector3f> points, const Eigen::Vector3f& camera,
                             size_t max, GLint count_location, GLint array_location) {
    static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "glUniform3fv reads packed xyz");
    const size_t count = std::min(points.size(), max);
    std::partial_sort(points.begin(), points.begin() + count, points.end(),
                      [&camera](const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
                        return (a - camera).head<2>().squaredNorm() <
                               (b - camera).head<2>().squaredNorm();
                      });
    glUniform1i(count_location, static_cast<GLint>(count));
    if (count > 0) {
      glUniform3fv(array_location, static_cast<GLsizei>(count), points.front().data());
    }
  }

  Framebuffer& framebuffer_of(int width, int height) {
    auto found = framebuffers.find({width, height});
    if (found == framebuffers.end()) {
      found = framebuffers.emplace(std::make_pair(width, height), Framebuffer{}).first;
      found->second.create(width, height);
    }
    return found->second;
  }
};

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {
  impl_->context.make_current();
  const GLubyte* name = glGetString(GL_RENDERER);
  impl_->device_name = name != nullptr ? reinterpret_cast<const char*>(name) : "unknown";
  impl_->program = link_program(kVertexShader.c_str(), kFragmentShader);
  impl_->world_to_optical_location = glGetUniformLocation(impl_->program, "world_to_optical");
  impl_->projection_location = glGetUniformLocation(impl_->program, "projection");
  impl_->camera_position_location = glGetUniformLocation(impl_->program, "camera_position");
  impl_->lamp_count_location = glGetUniformLocation(impl_->program, "lamp_count");
  impl_->lamps_location = glGetUniformLocation(impl_->program, "lamps");
  impl_->lamp_light_baked_location = glGetUniformLocation(impl_->program, "lamp_light_baked");
  impl_->contact_count_location = glGetUniformLocation(impl_->program, "contact_count");
  impl_->contacts_location = glGetUniformLocation(impl_->program, "contacts");
  impl_->static_mesh.create();
  impl_->static_mesh.add_baked_light();
  impl_->floor_mesh.create();
  impl_->floor_mesh.add_baked_light();
  impl_->dynamic_mesh.create();
  impl_->bake = std::make_unique<LampLightBake>();
}

Renderer::~Renderer() {
  impl_->context.make_current();
  for (auto& [size, framebuffer] : impl_->framebuffers) {
    framebuffer.destroy();
  }
  impl_->static_mesh.destroy();
  impl_->floor_mesh.destroy();
  impl_->dynamic_mesh.destroy();
  impl_->bake.reset();
  glDeleteProgram(impl_->program);
}

const std::string& Renderer::device_name() const {
  return impl_->device_name;
}

void Renderer::set_static_primitives(const std::vector<RenderPrimitive>& primitives) {
  impl_->context.make_current();
  std::vector<RenderPrimitive> floors, others;
  impl_->lamps.clear();
  for (const RenderPrimitive& primitive : primitives) {
    (primitive.surface == Surface::kFloor ? floors : others).push_back(primitive);
    if (primitive.surface == Surface::kLamp) {
      // The panel's lower face, which gives the light.
      impl_->lamps.push_back(
          (primitive.X_world_shape * Eigen::Vector3d(0.0, 0.0, -0.5 * primitive.size.z()))
              .cast<float>());
    }
  }
  RenderMesh floor = mesh_of(floors);
  shade_floor(floor_occluders_of(others), floor);
  impl_->floor_mesh.upload(floor);
  impl_->static_mesh.upload(mesh_of(others));
  // Every lamp lights the room; the people, lit every frame, by the kMaxLamps nearest the camera.
  for (const GpuMesh* mesh : {&impl_->floor_mesh, &impl_->static_mesh}) {
    impl_->bake->bake(mesh->array, mesh->vertex_count, impl_->lamps, mesh->baked_light);
  }
}

void Renderer::set_dynamic_primitives(const std::vector<RenderPrimitive>& primitives) {
  set_dynamic_mesh(mesh_of(primitives));
}

void Renderer::set_dynamic_mesh(const RenderMesh& mesh) {
  impl_->context.make_current();
  impl_->dynamic_mesh.upload(mesh);
  impl_->contacts = floor_contacts(mesh);
}

void Renderer::render(const PinholeModel& model, const Eigen::Isometry3d& X_world_optical,
                      const ViewOptions& options, RenderedImage& out) {
  impl_->context.make_current();
  Framebuffer& target = impl_->framebuffer_of(model.width, model.height);
  MultisampleTarget* multisample =
      options.samples > 1
          ? &impl_->multisample_target_of(model.width, model.height, options.samples)
          : nullptr;
  glBindFramebuffer(GL_FRAMEBUFFER, multisample ? multisample->framebuffer() : target.framebuffer);
  // Only the outputs asked for are written: a colour-only camera skips the depth and label
  // attachments' bandwidth, which is a good part of llvmpipe's cost per pixel.
  const GLenum draw_buffers[3] = {options.colour ? GLenum{GL_COLOR_ATTACHMENT0} : GLenum{GL_NONE},
                                  options.depth ? GLenum{GL_COLOR_ATTACHMENT1} : GLenum{GL_NONE},
                                  options.labels ? GLenum{GL_COLOR_ATTACHMENT2} : GLenum{GL_NONE}};
  glDrawBuffers(3, draw_buffers);
  glViewport(0, 0, model.width, model.height);

  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  if (options.colour) {
    glClearBufferfv(GL_COLOR, 0, kBackground);
  }
  if (options.depth) {
    glClearBufferfv(GL_COLOR, 1, zero);
  }
  if (options.labels) {
    glClearBufferfv(GL_COLOR, 2, zero);
  }
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  // Outward faces are counter-clockwise in the world; the y-down image flip makes them clockwise
  // on screen.
  glEnable(GL_CULL_FACE);
  glFrontFace(GL_CW);
  glCullFace(GL_BACK);

  glUseProgram(impl_->program);
  const Eigen::Matrix4f world_to_optical = X_world_optical.inverse().matrix().cast<float>();
  const Eigen::Matrix4f projection = projection_of(model, options.near_m, options.far_m);
  glUniformMatrix4fv(impl_->world_to_optical_location, 1, GL_FALSE, world_to_optical.data());
  glUniformMatrix4fv(impl_->projection_location, 1, GL_FALSE, projection.data());
  const Eigen::Vector3f camera_position = X_world_optical.translation().cast<float>();
  glUniform3fv(impl_->camera_position_location, 1, camera_position.data());
  Impl::upload_nearest(impl_->lamps, camera_position, Impl::kMaxLamps, impl_->lamp_count_location,
                       impl_->lamps_location);
  glUniform1i(impl_->contact_count_location, 0);
  glUniform1i(impl_->lamp_light_baked_location, 0);
  if (options.only_dynamic) {
    impl_->dynamic_mesh.draw(static_cast<GLint>(options.only_dynamic->first),
                             static_cast<GLsizei>(options.only_dynamic->count));
  } else {
    glUniform1i(impl_->lamp_light_baked_location, 1);
    impl_->static_mesh.draw();
    glUniform1i(impl_->lamp_light_baked_location, 0);
    impl_->dynamic_mesh.draw();
    glUniform1i(impl_->lamp_light_baked_location, 1);
    // The contact shadows' loop runs for the floor's vertices only: its count is theirs alone.
    Impl::upload_nearest(impl_->contacts, camera_position, Impl::kMaxContacts,
                         impl_->contact_count_location, impl_->contacts_location);
    impl_->floor_mesh.draw();
  }

  if (multisample) {
    multisample->resolve_into(target.framebuffer, draw_buffers);
  }

  // Read back; the first row read is window y = 0, which the projection made image row v = 0.
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (options.colour) {
    out.colour.create(model.height, model.width, CV_8UC3);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, model.width, model.height, GL_RGB, GL_UNSIGNED_BYTE, out.colour.data);
  }
  if (options.depth) {
    out.depth.create(model.height, model.width, CV_32FC1);
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    glReadPixels(0, 0, model.width, model.height, GL_RED, GL_FLOAT, out.depth.data);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    float* depth = out.depth.ptr<float>();
    const size_t count = out.depth.total();
    for (size_t i = 0; i < count; ++i) {
      if (depth[i] <= 0.0f) {
        depth[i] = nan;
      }
    }
  }
  if (options.labels) {
    impl_->label_scratch.create(model.height, model.width, CV_32FC1);
    glReadBuffer(GL_COLOR_ATTACHMENT2);
    glReadPixels(0, 0, model.width, model.height, GL_RED, GL_FLOAT, impl_->label_scratch.data);
    impl_->label_scratch.convertTo(out.labels, CV_16UC1);
  }
}

}  // namespace ari_social_sim::rendering
