// The primary-ray benchmark's reference: Intel Embree 3 builds its BVH over
// the benchmark mesh and traces one ray through the centre of every pixel
// with rtcIntersect1, one ray at a time, on THREADS threads (rows shared out
// as they finish), from the camera of the scene that run.sh writes. It is
// what RISE's Whitted ray tracer does for a scene without lights, less the
// shading: build, then one nearest hit a pixel. It prints the best and the
// mean of RUNS runs, each timed from the scene's creation to the last ray,
// and writes the last run's image (grey by the cosine between the ray and the
// triangle's normal, to see that it framed the mesh).
//
// usage: embree_primary MESH.ply WIDTH HEIGHT THREADS RUNS OUT.ppm
// The mesh is make_mesh.py's binary PLY: float properties per vertex (x y z
// first), triangles as a uchar 3 and three ints.
#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

// The camera of primary.yaml, which run.sh writes.
constexpr std::array<float, 3> kEye = {0.6f, 0.9f, -2.6f};
constexpr std::array<float, 3> kLookAt = {0.0f, 0.0f, 0.0f};
constexpr std::array<float, 3> kUp = {0.0f, 1.0f, 0.0f};
constexpr float kFovDegrees = 45.0f;

using Vec = std::array<float, 3>;

Vec operator-(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec operator+(const Vec& a, const Vec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec operator*(float s, const Vec& v) { return {s * v[0], s * v[1], s * v[2]}; }
float dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec normalize(const Vec& v) { return (1.0f / std::sqrt(dot(v, v))) * v; }

struct Mesh {
  std::vector<float> positions;  // x y z, then one unused float: Embree reads 16 bytes
  std::vector<std::uint32_t> indices;
};

Mesh readPly(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::size_t vertexCount = 0, faceCount = 0, floatsPerVertex = 0;
  std::string element;
  for (std::string line; std::getline(in, line) && line != "end_header";) {
    std::istringstream words(line);
    std::string keyword, type;
    words >> keyword;
    if (keyword == "element") {
      std::size_t count = 0;
      words >> element >> count;
      (element == "vertex" ? vertexCount : faceCount) = count;
    } else if (keyword == "property" && element == "vertex" && words >> type) {
      if (type != "float") throw std::runtime_error("a vertex property is not a float");
      ++floatsPerVertex;
    }
  }
  if (floatsPerVertex < 3) throw std::runtime_error("the vertices have no x y z");
  Mesh mesh;
  std::vector<float> vertices(floatsPerVertex * vertexCount);
  in.read(reinterpret_cast<char*>(vertices.data()),
          static_cast<std::streamsize>(vertices.size() * sizeof(float)));
  mesh.positions.resize(4 * vertexCount + 1);
  for (std::size_t vertex = 0; vertex < vertexCount; ++vertex)
    std::copy_n(&vertices[floatsPerVertex * vertex], 3, &mesh.positions[4 * vertex]);
  mesh.indices.resize(3 * faceCount);
  for (std::size_t face = 0; face < faceCount; ++face) {
    unsigned char corners = 0;
    in.read(reinterpret_cast<char*>(&corners), 1);
    in.read(reinterpret_cast<char*>(&mesh.indices[3 * face]), 3 * sizeof(std::uint32_t));
    if (corners != 3) throw std::runtime_error("not a triangle mesh");
  }
  if (!in) throw std::runtime_error(path + " is cut short");
  return mesh;
}

RTCScene buildScene(RTCDevice device, const Mesh& mesh) {
  RTCScene scene = rtcNewScene(device);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                             mesh.positions.data(), 0, 4 * sizeof(float),
                             (mesh.positions.size() - 1) / 4);
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                             mesh.indices.data(), 0, 3 * sizeof(std::uint32_t),
                             mesh.indices.size() / 3);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  return scene;
}

// RISE's pinhole camera (scene/camera.cpp): a vertical field of view, rays
// through the pixels' centres.
class Camera {
 public:
  Camera(int width, int height) : width_(width), height_(height) {
    forward_ = normalize(kLookAt - kEye);
    right_ = normalize(cross(forward_, kUp));
    up_ = cross(right_, forward_);
    halfHeight_ = std::tan(kFovDegrees * 3.14159265358979f / 180.0f * 0.5f);
    halfWidth_ = halfHeight_ * static_cast<float>(width) / static_cast<float>(height);
  }

  Vec direction(int x, int y) const {
    const float sx = (2.0f * (x + 0.5f) / static_cast<float>(width_) - 1.0f) * halfWidth_;
    const float sy = (1.0f - 2.0f * (y + 0.5f) / static_cast<float>(height_)) * halfHeight_;
    return normalize(forward_ + sx * right_ + sy * up_);
  }

 private:
  int width_, height_;
  Vec forward_, right_, up_;
  float halfWidth_, halfHeight_;
};

void traceRows(RTCScene scene, const Camera& camera, int width, std::atomic<int>& nextRow,
               int height, std::vector<unsigned char>& image) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (int y = nextRow++; y < height; y = nextRow++) {
    for (int x = 0; x < width; ++x) {
      const Vec direction = camera.direction(x, y);
      RTCRayHit rayHit{};
      rayHit.ray.org_x = kEye[0];
      rayHit.ray.org_y = kEye[1];
      rayHit.ray.org_z = kEye[2];
      rayHit.ray.dir_x = direction[0];
      rayHit.ray.dir_y = direction[1];
      rayHit.ray.dir_z = direction[2];
      rayHit.ray.tfar = INFINITY;
      rayHit.ray.mask = ~0u;
      rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene, &context, &rayHit);
      unsigned char grey = 25;
      if (rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
        const Vec normal = normalize({rayHit.hit.Ng_x, rayHit.hit.Ng_y, rayHit.hit.Ng_z});
        grey = static_cast<unsigned char>(255.0f * std::abs(dot(normal, direction)));
      }
      std::fill_n(&image[3 * (static_cast<std::size_t>(y) * width + x)], 3, grey);
    }
  }
}

// One run: build, then trace every pixel; returns its seconds.
double run(RTCDevice device, const Mesh& mesh, int width, int height, int threads,
           std::vector<unsigned char>& image) {
  const auto start = std::chrono::steady_clock::now();
  RTCScene scene = buildScene(device, mesh);
  const Camera camera(width, height);
  std::atomic<int> nextRow{0};
  std::vector<std::thread> workers;
  for (int i = 1; i < threads; ++i)
    workers.emplace_back(traceRows, scene, std::cref(camera), width, std::ref(nextRow), height,
                         std::ref(image));
  traceRows(scene, camera, width, nextRow, height, image);
  for (std::thread& worker : workers) worker.join();
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  rtcReleaseScene(scene);
  return seconds.count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 7) {
    std::cerr << "usage: embree_primary MESH.ply WIDTH HEIGHT THREADS RUNS OUT.ppm\n";
    return 2;
  }
  try {
    const Mesh mesh = readPly(argv[1]);
    const int width = std::stoi(argv[2]), height = std::stoi(argv[3]);
    const int threads = std::stoi(argv[4]), runs = std::stoi(argv[5]);
    const std::string configuration = "threads=" + std::to_string(threads);
    RTCDevice device = rtcNewDevice(configuration.c_str());
    if (device == nullptr) throw std::runtime_error("Embree refused the device");
    std::vector<unsigned char> image(3 * static_cast<std::size_t>(width) * height);
    double best = INFINITY, total = 0.0;
    for (int i = 0; i < runs; ++i) {
      const double seconds = run(device, mesh, width, height, threads, image);
      best = std::min(best, seconds);
      total += seconds;
    }
    rtcReleaseDevice(device);
    std::ofstream out(argv[6], std::ios::binary);
    out << "P6\n" << width << " " << height << "\n255\n";
    out.write(reinterpret_cast<const char*>(image.data()),
              static_cast<std::streamsize>(image.size()));
    std::cout << "triangles " << mesh.indices.size() / 3 << "\n"
              << "best_seconds " << best << "\n"
              << "mean_seconds " << total / runs << "\n";
    return out ? 0 : 1;
  } catch (const std::exception& error) {
    std::cerr << "embree_primary: " << error.what() << "\n";
    return 1;
  }
}
