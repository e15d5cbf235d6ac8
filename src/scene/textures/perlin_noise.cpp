#include "scene/textures/perlin_noise.hpp"

#include <array>
#include <cmath>

namespace rise {

namespace {

// Perlin's reference permutation of 0..255.
constexpr std::array<int, 256> kPermutation{
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103,
    30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,
    197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174,
    20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231,
    83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143,
    54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196,
    135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124,
    123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,
    182, 189, 28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101,
    155, 167, 43,  172, 9,   129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185,
    112, 104, 218, 246, 97,  228, 251, 34,  242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,
    51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176,
    115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243,
    141, 128, 195, 78,  66,  215, 61,  156, 180};

int permuted(int i) { return kPermutation[i & 255]; }

float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

// The dot product of the offset with one of the twelve gradients, chosen by
// the hash's low four bits (four of the sixteen repeat, as in Perlin's code).
float gradient(int hash, float x, float y, float z) {
  const int h = hash & 15;
  const float u = h < 8 ? x : y;
  const float v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
  return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
}

}  // namespace

float perlinNoise(const Vec3& point) {
  const Vec3 floor = glm::floor(point);
  const int X = static_cast<int>(floor.x) & 255;
  const int Y = static_cast<int>(floor.y) & 255;
  const int Z = static_cast<int>(floor.z) & 255;
  const Vec3 f = point - floor;
  const float u = fade(f.x), v = fade(f.y), w = fade(f.z);
  const int A = permuted(X) + Y, AA = permuted(A) + Z, AB = permuted(A + 1) + Z;
  const int B = permuted(X + 1) + Y, BA = permuted(B) + Z, BB = permuted(B + 1) + Z;
  const auto lerp = [](float t, float a, float b) { return a + t * (b - a); };
  return lerp(w,
              lerp(v,
                   lerp(u, gradient(permuted(AA), f.x, f.y, f.z),
                        gradient(permuted(BA), f.x - 1, f.y, f.z)),
                   lerp(u, gradient(permuted(AB), f.x, f.y - 1, f.z),
                        gradient(permuted(BB), f.x - 1, f.y - 1, f.z))),
              lerp(v,
                   lerp(u, gradient(permuted(AA + 1), f.x, f.y, f.z - 1),
                        gradient(permuted(BA + 1), f.x - 1, f.y, f.z - 1)),
                   lerp(u, gradient(permuted(AB + 1), f.x, f.y - 1, f.z - 1),
                        gradient(permuted(BB + 1), f.x - 1, f.y - 1, f.z - 1))));
}

float turbulence(const Vec3& point, int octaves) {
  float sum = 0.0f;
  float frequency = 1.0f;
  for (int octave = 0; octave < octaves; ++octave, frequency *= 2.0f)
    sum += std::abs(perlinNoise(frequency * point)) / frequency;
  return sum;
}

}  // namespace rise
