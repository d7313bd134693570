// The XML document walk (scene/xml_walk.h): <SceneLevel> and its elements, the shapes
// (each a shape kind that parses itself, shapes/<kind>.h, found through the list of
// kinds; <Mesh> reads files: xml_meshes.cpp), and the materials: <Attenuate> and <Emit>
// around a material are the walk's own; every other element is a material kind that
// parses itself (materials/<kind>.h), found through the list of kinds. Strict: unknown elements and attributes are errors with their line.
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "core/file_io.h"
#include "scene/env_map.h"
#include "scene/textured_loader.h"
#include "scene/xml_walk.h"

namespace pt {

using tinyxml2::XMLElement;

namespace {

template <class K>
void parse_shape(XmlAttrs& a, Shape& s) {
  if constexpr (!KindLoadedByLoader<K>::value) {
    K k;
    k.parse(a);
    s.set(std::move(k));
  }
}

}  // namespace

std::string Loader::resolve_path(XmlAttrs& a, const std::string& p) {
  if (!allow_files) a.fail("file references are disabled for this scene text");
  std::string r = !p.empty() && p[0] == '/' ? p : directory_of(file) + "/" + p;
  scene.files.push_back(r);
  return r;
}

std::shared_ptr<const EnvImage> Loader::load_env_image(XmlAttrs& a, const std::string& path) {
  try {
    return load_env_map(path);
  } catch (const std::runtime_error& e) {
    a.fail(e.what());
  }
}

void Loader::fail(const XMLElement* e, const std::string& what) {
  throw InputError(file, e ? e->GetLineNum() : 0, what);
}

int Loader::material(const XMLElement* e, glm::vec3 tint) {
  if (!std::strcmp(e->Name(), "Attenuate")) {
    XmlAttrs a(e, file);
    const glm::vec3 c = a.vec3("color");
    if (glm::any(glm::lessThan(c, glm::vec3(0.0f))) || glm::any(glm::greaterThan(c, glm::vec3(1.0f))))
      a.fail("'color' components must be in [0, 1]");
    a.finish();
    const XMLElement* inner = e->FirstChildElement();
    if (!inner || inner->NextSiblingElement()) a.fail("must wrap exactly one material");
    return material(inner, tint * c);
  }
  // <Emit intensity=".." color=".."> around a material that is not <Absorb>: a surface that
  // emits and also scatters (an extension of the seed's Emit+Absorb; the closed-form tests
  // use it for walls of albedo rho and emission Le).
  const XMLElement* first = e->FirstChildElement();
  if (!std::strcmp(e->Name(), "Emit") && first && std::strcmp(first->Name(), "Absorb") != 0) {
    XmlAttrs a(e, file);
    const float intensity = a.number("intensity");
    const glm::vec3 color = a.vec3("color", glm::vec3(1.0f));
    if (intensity < 0.0f || glm::any(glm::lessThan(color, glm::vec3(0.0f)))) a.fail("intensity and color must be >= 0");
    a.finish();
    if (first->NextSiblingElement()) a.fail("must wrap exactly one material");
    const int inner = material(first, tint);
    scene.materials[size_t(inner)].emission += color * intensity;
    return inner;
  }
  // One of the kinds (materials/kinds.h): its stem parses its attributes (and children).
  Material m;
  m.tint = tint;
  m.line = e->GetLineNum();
  XmlAttrs a(e, file);
  bool found = false, has_children = false;
#define PT_X(k, g, x)                         \
  if (!found && !std::strcmp(e->Name(), x)) { \
    k params;                                 \
    MaterialParse p{a, e, m, *this};          \
    params.parse(p);                          \
    m.params = std::move(params);             \
    has_children = KindHasChildren<k>::value; \
    found = true;                             \
  }
  PT_MATERIAL_KINDS(PT_X)
#undef PT_X
  if (!found) fail(e, "unknown material <" + std::string(e->Name()) + ">");
  a.finish();
  if (!has_children && e->FirstChildElement()) a.fail("takes no child elements");
  scene.materials.push_back(m);
  return int(scene.materials.size()) - 1;
}

int Loader::child(const XMLElement* e, glm::vec3 tint) {
  ++composite_depth_;
  const int i = material(e, tint);
  --composite_depth_;
  return i;
}

int Loader::image_map(XmlAttrs& a, const char* attr, bool normal) {
  return load_image_map(a, scene, attr, normal, [this](XmlAttrs& at, const std::string& p) { return resolve_path(at, p); });
}

int Loader::image_map_linear(XmlAttrs& a, const char* attr) {
  if (!a.has(attr)) return -1;
  const std::string given = a.text(attr);
  const std::string path = resolve_path(a, given);
  LoadedImage img;
  std::string why;
  if (!read_image(path, &img, &why)) a.fail("cannot read '" + given + "': " + why);
  return add_linear_image_map(scene, path, img, a.line(), [&](const std::string& what) { a.fail("'" + given + "' " + what); });
}

void Loader::shape(const XMLElement* e) {
  // One of the kinds (shapes/kinds.h): its stem parses its attributes, except a kind whose
  // element reads files (<Mesh>: Loader::mesh).
  Shape s;
  s.line = e->GetLineNum();
  bool found = false;
#define PT_X(k, g, x, l, r, b)                          \
  if (!found && !std::strcmp(e->Name(), x)) {           \
    if (KindLoadedByLoader<k>::value) return mesh(e);   \
    XmlAttrs a(e, file);                                \
    parse_shape<k>(a, s);                               \
    s.dynamic = a.boolean("isDynamic", false);          \
    a.finish();                                         \
    found = true;                                       \
  }
  PT_SHAPE_KINDS(PT_X)
#undef PT_X
  if (!found) fail(e, "unknown object <" + std::string(e->Name()) + ">");
  const XMLElement* m = e->FirstChildElement();
  if (!m || m->NextSiblingElement()) XmlAttrs(e, file).fail("needs exactly one material element inside");
  s.material = material(m, glm::vec3(1.0f));
  scene.shapes.push_back(s);
}

void Loader::camera(const XMLElement* e) {
  XmlAttrs a(e, file);
  Camera& c = scene.camera;
  c.position = a.vec3("position");
  c.up = a.vec3("up", glm::vec3(0.0f, 1.0f, 0.0f));
  if (!(glm::length(c.up) > 0.0f)) a.fail("'up' must be non-zero");
  c.up = glm::normalize(c.up);
  c.yaw = a.number("yaw", 0.0f);
  c.pitch = a.number("pitch", 0.0f);
  // Any angle is a view (pitch 90 looks straight up, beyond it the image is upside down,
  // as in the 2016 program); only a view along 'up' has no right vector (camera_basis).
  if (!(glm::length(glm::cross(camera_forward(c), c.up)) > 1e-9f))
    a.fail("the view direction (yaw, pitch) is parallel to 'up': no image orientation");
  // Extensions: a thin lens and a shutter interval.
  c.aperture = a.number("aperture", 0.0f);
  c.focal_distance = a.number("focalDistance", 1.0f);
  c.shutter = a.number("shutter", 0.0f);
  if (c.aperture < 0.0f || !(c.focal_distance > 0.0f) || c.shutter < 0.0f)
    a.fail("'aperture' and 'shutter' must be >= 0 and 'focalDistance' > 0");
  a.finish();
  if (e->FirstChildElement()) a.fail("takes no child elements");
}

void Loader::light(const XMLElement* e) {
  XmlAttrs a(e, file);
  Light l;
  l.position = a.vec3("position");
  l.radius = a.number("radius", 1.0f);
  l.color = a.vec3("color", glm::vec3(1.0f));
  l.intensity = a.number("intensity", 1.0f);
  const glm::vec3 velocity = parse_motion(a, l.position);
  if (!(l.radius > 0.0f)) a.fail("'radius' must be positive");
  if (l.intensity < 0.0f || glm::any(glm::lessThan(l.color, glm::vec3(0.0f)))) a.fail("intensity and color must be >= 0");
  a.finish();
  if (e->FirstChildElement()) a.fail("takes no child elements");
  // A light is an emissive sphere that next-event estimation also samples.
  Material m = Emit{};
  m.emission = l.radiance();
  m.line = e->GetLineNum();
  scene.materials.push_back(m);
  Shape s(Sphere{.center = l.position, .radius = l.radius, .velocity = velocity}, int(scene.materials.size()) - 1);
  s.light = int(scene.lights.size());
  s.dynamic = true;
  s.line = e->GetLineNum();
  l.shape = int(scene.shapes.size());
  scene.shapes.push_back(s);
  scene.lights.push_back(l);
}

void Loader::render_settings(const XMLElement* e) {
  XmlAttrs a(e, file);
  SceneRender& r = scene.render;
  auto integer = [&](const char* name, float lo, float hi) {
    const float v = a.number(name);
    if (!(v >= lo && v <= hi && v == std::floor(v)))
      a.fail("'" + std::string(name) + "' must be an integer in " + std::to_string(int(lo)) + ".." + std::to_string(int(hi)));
    return int(v);
  };
  if (a.has("bounces")) r.bounces = integer("bounces", 1.0f, 64.0f);
  if (a.has("samples")) r.samples = integer("samples", 0.0f, 16777216.0f);
  if (a.has("mode")) {
    RenderMode m;
    if (!render_mode_from_name(a.text("mode").c_str(), &m)) a.fail("'mode' must be path, whitted or sh");
    r.mode = m;
  }
  if (a.has("tonemap")) {
    ToneMap t;
    if (!tonemap_from_name(a.text("tonemap").c_str(), &t))
      a.fail("'tonemap' must be one of none, linear, reinhard, filmic, srgb, uncharted2, aces");
    r.tonemap = t;
  }
  if (a.has("exposure")) {
    r.exposure = a.number("exposure");
    if (!(*r.exposure > 0.0f)) a.fail("'exposure' must be positive");
  }
  a.finish();
  if (e->FirstChildElement()) a.fail("takes no child elements");
}

void Loader::root(const XMLElement* r) {
  if (!r || std::strcmp(r->Name(), "SceneLevel") != 0) fail(r, "the root element must be <SceneLevel>");
  XmlAttrs a(r, file);
  scene.dot_weight = a.boolean("dotWeight", true);
  a.finish();
  bool have_camera = false, have_objects = false, have_env = false, have_render = false;
  for (const XMLElement* e = r->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const char* n = e->Name();
    if (!std::strcmp(n, "Camera")) {
      if (have_camera) fail(e, "a second <Camera>");
      have_camera = true;
      camera(e);
    } else if (!std::strcmp(n, "Light")) {
      light(e);
    } else if (XmlAttrs la(e, file); std::optional<LightParams> l = parse_light_element(n, la)) {
      // <PointLight>, <SpotLight>, <DirectionalLight> (lights/kinds.h: the kind's stem parses it)
      la.finish();
      if (e->FirstChildElement()) la.fail("takes no child elements");
      scene.punctual.push_back({*l, e->GetLineNum()});
    } else if (!std::strcmp(n, "Environment")) {
      if (have_env) fail(e, "a second <Environment>");
      have_env = true;
      environment(e);
    } else if (!std::strcmp(n, "Render")) {
      if (have_render) fail(e, "a second <Render>");
      have_render = true;
      render_settings(e);
    } else if (!std::strcmp(n, "Objects")) {
      if (have_objects) fail(e, "a second <Objects>");
      have_objects = true;
      XmlAttrs(e, file).finish();
      for (const XMLElement* o = e->FirstChildElement(); o; o = o->NextSiblingElement()) shape(o);
    } else {
      fail(e, "unknown element <" + std::string(n) + "> in <SceneLevel>");
    }
  }
  if (!have_camera) fail(r, "<SceneLevel> needs a <Camera>");
  if (scene.shapes.empty()) fail(r, "the scene has no objects and no lights");
}

// Extension: <Environment color="r g b"/> (the constant radiance of rays that leave the
// scene; default 0.5 grey, the seed's constant environment) or <Environment map="sky.hdr"
// rotation="deg" intensity="k"/>.
void Loader::environment(const XMLElement* e) {
  XmlAttrs env(e, file);
  Environment& en = scene.environment;
  if (env.has("map") == env.has("color")) env.fail("give either 'color' or 'map'");
  if (env.has("color")) {
    en.color = env.vec3("color");
    if (glm::any(glm::lessThan(en.color, glm::vec3(0.0f)))) env.fail("'color' must be >= 0");
  } else {
    en.map_path = resolve_path(env, env.text("map"));
    en.map = load_env_image(env, en.map_path);
    en.rotation = env.number("rotation", 0.0f);
    en.intensity = env.number("intensity", 1.0f);
    if (en.intensity < 0.0f) env.fail("'intensity' must be >= 0");
  }
  env.finish();
  if (e->FirstChildElement()) env.fail("takes no child elements");
}

}  // namespace pt
