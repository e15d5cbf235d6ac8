// The benchmark's reference: Mesa's software OpenGL (llvmpipe, through
// OSMesa) draws the benchmark mesh as fixed-function OpenGL 1.x draws it, with
// a depth buffer, back faces culled and Gouraud shading (the lighting model
// evaluated at the vertices, colours interpolated), one point light, from the
// camera of RISE's scene. It prints the time of the best frame and of their
// mean, each measured from the clear to glFinish, and writes the last frame.
//
// usage: osmesa_gouraud MESH.ply WIDTH HEIGHT FRAMES OUT.ppm
// The mesh is make_mesh.py's binary PLY: float x y z nx ny nz per vertex,
// triangles as a uchar 3 and three ints.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

// The scene of million.yaml, which run.sh writes: camera, light, material.
constexpr std::array<float, 3> kEye = {0.6f, 0.9f, -2.6f};
constexpr std::array<float, 3> kLookAt = {0.0f, 0.0f, 0.0f};
constexpr float kFovDegrees = 45.0f;
constexpr std::array<float, 4> kLightPosition = {-3.0f, 4.0f, -4.0f, 1.0f};
constexpr std::array<float, 4> kAmbientLight = {0.1f, 0.1f, 0.1f, 1.0f};
constexpr std::array<float, 3> kColor = {0.8f, 0.55f, 0.35f};
constexpr float kKa = 1.0f, kKd = 0.8f, kKs = 0.3f, kShininess = 20.0f;
constexpr std::array<float, 4> kBackground = {0.05f, 0.05f, 0.1f, 1.0f};

struct Mesh {
  std::vector<float> vertices;  // x y z nx ny nz
  std::vector<std::uint32_t> indices;
};

Mesh readPly(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::size_t vertexCount = 0, faceCount = 0;
  for (std::string line; std::getline(in, line) && line != "end_header";) {
    std::istringstream words(line);
    std::string keyword, element;
    std::size_t count;
    if (words >> keyword >> element >> count && keyword == "element")
      (element == "vertex" ? vertexCount : faceCount) = count;
  }
  Mesh mesh;
  mesh.vertices.resize(6 * vertexCount);
  in.read(reinterpret_cast<char*>(mesh.vertices.data()),
          static_cast<std::streamsize>(mesh.vertices.size() * sizeof(float)));
  mesh.indices.resize(3 * faceCount);
  for (std::size_t face = 0; face < faceCount; ++face) {
    unsigned char corners;
    in.read(reinterpret_cast<char*>(&corners), 1);
    in.read(reinterpret_cast<char*>(&mesh.indices[3 * face]), 3 * sizeof(std::uint32_t));
    if (corners != 3) throw std::runtime_error("not a triangle mesh");
  }
  if (!in) throw std::runtime_error(path + " is cut short");
  return mesh;
}

// gluLookAt's matrix, column-major.
std::array<float, 16> lookAt() {
  const auto normalize = [](std::array<float, 3> v) {
    const float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return std::array<float, 3>{v[0] / length, v[1] / length, v[2] / length};
  };
  const auto cross = [](const std::array<float, 3>& a, const std::array<float, 3>& b) {
    return std::array<float, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                a[0] * b[1] - a[1] * b[0]};
  };
  const auto f = normalize({kLookAt[0] - kEye[0], kLookAt[1] - kEye[1], kLookAt[2] - kEye[2]});
  const auto s = normalize(cross(f, {0.0f, 1.0f, 0.0f}));
  const auto u = cross(s, f);
  std::array<float, 16> m = {s[0], u[0], -f[0], 0.0f, s[1], u[1], -f[1], 0.0f,
                             s[2], u[2], -f[2], 0.0f, 0.0f, 0.0f, 0.0f,  1.0f};
  for (int row = 0; row < 3; ++row)
    m[12 + row] = -(m[row] * kEye[0] + m[4 + row] * kEye[1] + m[8 + row] * kEye[2]);
  return m;
}

void setUpScene(int width, int height) {
  glViewport(0, 0, width, height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double nearPlane = 0.01, farPlane = 100.0;
  const double top = nearPlane * std::tan(0.5 * kFovDegrees * M_PI / 180.0);
  const double right = top * width / height;
  glFrustum(-right, right, -top, top, nearPlane, farPlane);
  glMatrixMode(GL_MODELVIEW);
  const std::array<float, 16> view = lookAt();
  glLoadMatrixf(view.data());

  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glShadeModel(GL_SMOOTH);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, kAmbientLight.data());
  const std::array<float, 4> white = {1.0f, 1.0f, 1.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, kLightPosition.data());
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white.data());
  glLightfv(GL_LIGHT0, GL_SPECULAR, white.data());
  const std::array<float, 4> ambient = {kKa * kColor[0], kKa * kColor[1], kKa * kColor[2], 1.0f};
  const std::array<float, 4> diffuse = {kKd * kColor[0], kKd * kColor[1], kKd * kColor[2], 1.0f};
  const std::array<float, 4> specular = {kKs, kKs, kKs, 1.0f};
  glMaterialfv(GL_FRONT, GL_AMBIENT, ambient.data());
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse.data());
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular.data());
  glMaterialf(GL_FRONT, GL_SHININESS, kShininess);
  glClearColor(kBackground[0], kBackground[1], kBackground[2], kBackground[3]);
}

// The mesh in buffer objects, drawn from them each frame.
void upload(const Mesh& mesh) {
  GLuint buffers[2];
  glGenBuffers(2, buffers);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(float)),
               mesh.vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 6 * sizeof(float), nullptr);
  glNormalPointer(GL_FLOAT, 6 * sizeof(float), reinterpret_cast<const void*>(3 * sizeof(float)));
}

double drawFrame(std::size_t indexCount) {
  const auto start = std::chrono::steady_clock::now();
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indexCount), GL_UNSIGNED_INT, nullptr);
  glFinish();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// OpenGL's rows run bottom to top; PPM's top to bottom.
void writePpm(const std::string& path, const std::vector<unsigned char>& rgba, int width,
              int height) {
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << width << " " << height << "\n255\n";
  for (int y = height - 1; y >= 0; --y)
    for (int x = 0; x < width; ++x)
      out.write(reinterpret_cast<const char*>(&rgba[4 * (y * width + x)]), 3);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) {
    std::cerr << "usage: osmesa_gouraud MESH.ply WIDTH HEIGHT FRAMES OUT.ppm\n";
    return 2;
  }
  const int width = std::atoi(argv[2]), height = std::atoi(argv[3]), frames = std::atoi(argv[4]);
  const Mesh mesh = readPly(argv[1]);
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  std::vector<unsigned char> pixels(static_cast<std::size_t>(4) * width * height);
  if (!context || !OSMesaMakeCurrent(context, pixels.data(), GL_UNSIGNED_BYTE, width, height)) {
    std::cerr << "osmesa_gouraud: no OSMesa context\n";
    return 1;
  }
  setUpScene(width, height);
  upload(mesh);
  drawFrame(mesh.indices.size());  // the first frame compiles llvmpipe's shaders
  double best = 1e30, total = 0.0;
  for (int frame = 0; frame < frames; ++frame) {
    const double seconds = drawFrame(mesh.indices.size());
    best = std::min(best, seconds);
    total += seconds;
  }
  writePpm(argv[5], pixels, width, height);
  std::cout << "renderer " << glGetString(GL_RENDERER) << "\n";
  std::cout << "best_seconds " << best << "\nmean_seconds " << total / frames << "\n";
  OSMesaDestroyContext(context);
  return 0;
}
