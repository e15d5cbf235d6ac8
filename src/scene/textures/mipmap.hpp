// A mipmap (L. Williams, "Pyramidal Parametrics", SIGGRAPH 1983): the image,
// then each level half the one before, each texel the mean of the 2 x 2
// it covers, down to a single texel; and two ways to read it over a pixel's
// footprint in the texture (texture.hpp), the parallelogram spanned by the
// steps of the texture coordinates to the next pixel across and down:
//
//   trilinear  Williams': the two levels whose texels are about as wide as
//              the footprint's longer side, read bilinearly and blended. A
//              square filter: where the footprint is long and thin (a floor
//              seen at a grazing angle) it blurs across it as much as along.
//   elliptical Heckbert's elliptical weighted average (P. S. Heckbert,
//              "Fundamentals of Texture Mapping and Image Warping", Master's
//              thesis, UC Berkeley, 1989; N. Greene and P. S. Heckbert,
//              IEEE CG&A 6(6), 1986): a Gaussian over the ellipse the pixel
//              covers, summed texel by texel on the level where the
//              ellipse's shorter axis is about a texel wide, so that it
//              blurs along a long footprint alone.
#pragma once

#include <vector>

#include "core/image.hpp"
#include "scene/textures/texture.hpp"

namespace rise {

class MipMap {
 public:
  // Builds every level, halving the image until a single texel is left.
  explicit MipMap(const Image& image);
  const std::vector<Image>& levels() const { return levels_; }

  Color trilinearAt(const Vec2& uv, const PixelFootprint& footprint) const;
  Color ellipticalAverageAt(const Vec2& uv, const PixelFootprint& footprint) const;

 private:
  // The ellipse { J w : |w| <= 1 } of the footprint's steps J, in texels of
  // level 0 (x right, y down), as the symmetric matrix J J^T.
  struct Ellipse {
    float xx, xy, yy;
    // Its half-axes squared: the eigenvalues of J J^T.
    float longerSquared() const;
    float shorterSquared() const;
  };
  Ellipse ellipseOf(const PixelFootprint& footprint) const;
  Color ellipticalAverageOn(int level, const Vec2& uv, const Ellipse& ellipse) const;
  // The level between two, whose texels are `texels` of level 0 wide.
  float levelFor(float texels) const;

  std::vector<Image> levels_;
};

}  // namespace rise
