// Numeric test (no baseline) of vtkPlumeAirlightPass's airlight lattice
// (Downsampling D > 1: the airlight on a node every D pixels, interpolated
// bilinearly in cells the classification passes, every pixel evaluated in
// the others) against the independent double-precision
// vtkPlumeAirlightReference at every pixel: a room with a box and a sphere
// (depth edges), a point light in view (its glow peaks between nodes) and a
// spot light with exponent 2 whose cone edges cross the view, coloured haze.
// At every D (1, 2, 4, 8) and number of lattice levels the whole image, the
// pixels at depth edges and the pixels near the light's image meet the
// issue's goal (RMS <= 0.5 %, max <= 2 % of the airlight range); the lattice
// really interpolates (some cells, not all, refined; the image differs from
// the per-pixel one), and a finer level evaluates fewer pixels exactly than
// one level of the same spacing; at the nodes' pixels the frame is the
// per-pixel one (the interpolation's geometry, the narrower last cells
// included). Thin poles between the nodes are refined (one away from the
// lights: its pixels are the per-pixel ones); with them and shadows on, the
// frame is the per-pixel one.
#include "plumeAirlightTestUtil.h"

int TestAirlightLattice(int, char*[])
{
  int failures = 0;
  auto setUp = [](airtest::Scene& s) {
    s.AddRoom();
    s.AddPointLight(0.6, 2.2, -2.6, 1.0, 0.85, 0.6, 0.6);
    const double sp[3] = { 2.5, 3.5, -1.5 }, sf[3] = { 0.5, 0.0, -1.5 };
    s.AddSpotLight(sp, sf, 35.0, 2.0, 0.7, 0.8, 1.0, 1.0);
    s.Pass->SetScattering(0.25, 0.2, 0.15);
    s.Pass->SetAbsorption(0.02, 0.04, 0.08);
    s.Pass->SetIntensityScale(30.0);
    s.Camera(0.5, 1.6, 6.0, -0.3, 1.2, -2.0);
  };
  // Clamped to [0, 1] as the window shows them (the light's glow exceeds 1
  // nearby: unclamped, the range would be 30 and every error tiny against it).
  auto render = [&failures](airtest::Scene& s) {
    airtest::FloatImage image = s.RenderFloat(s.Pass);
    PLUME_CHECK(!plume::test::HasNonFinite(image));
    for (float& v : image.RGBA)
    {
      v = std::min(std::max(v, 0.0f), 1.0f);
    }
    return image;
  };

  // A frame whose size is no multiple of D: the last cell of every row and
  // column is D + 1 pixels wide (97 = 12 x 8 + 1), drawn as a quad, the other
  // refined cells as points of D pixels (plume::DrawLatticeCells). Each
  // refined pixel must get its airlight exactly once: every pixel against
  // the reference, one and two levels.
  {
    airtest::Scene odd(97, 73);
    setUp(odd);
    airtest::FloatImage oddAir;
    const airtest::FloatImage oddRef = odd.Reference(odd.RenderFloat(nullptr), 1, &oddAir);
    for (int levels = 1; levels <= 2; ++levels)
    {
      odd.Pass->SetLatticeLevels(levels);
      const airtest::Error e = airtest::Compare(render(odd), oddRef, oddAir);
      std::cout << "97 x 73, downsampling 8, " << levels << " level(s), refined cells "
                << odd.Pass->GetLastRefinedCellFraction() << ":\n";
      airtest::Print("  all pixels", e);
      PLUME_CHECK(plume::test::GLErrors(odd.Window).empty());
      PLUME_CHECK(e.Range > 0.5);
      PLUME_CHECK(e.RMS <= 0.005);
      PLUME_CHECK(e.Max <= 0.02);
      PLUME_CHECK(odd.Pass->GetLastRefinedCellFraction() > 0.0);
    }
    // Every cell refined (tolerance 0: no haze is linear between nodes): the
    // frame is the per-pixel one up to rounding, so a pixel covered twice or
    // not at all shows (the last cells drawn as D-pixel points: 0.018 off).
    odd.Pass->SetLatticeLevels(1);
    odd.Pass->SetUpsamplingTolerance(0.0);
    const airtest::FloatImage allRefined = render(odd);
    PLUME_CHECK(odd.Pass->GetLastRefinedCellFraction() == 1.0);
    odd.Pass->SetDownsampling(1);
    const airtest::Error vsFull = airtest::Compare(allRefined, render(odd), oddAir);
    airtest::Print("  every cell refined, against the per-pixel pass", vsFull);
    PLUME_CHECK(vsFull.Max * vsFull.Range <= 1e-5);
  }

  const int W = 160, H = 120;
  airtest::Scene s(W, H);
  setUp(s);
  const airtest::FloatImage plain = s.RenderFloat(nullptr);
  airtest::FloatImage air;
  const airtest::FloatImage ref = s.Reference(plain, 1, &air);
  s.Pass->SetDownsampling(1);
  const airtest::FloatImage full = render(s);

  // Depth-edge pixels: the surface distance (window depth) jumps to a
  // 4-neighbour, or the surface ends. Near-light pixels: within 12 pixels of
  // the point light's image.
  double light[3] = { 0.6, 2.2, -2.6 };
  s.Renderer->SetWorldPoint(light[0], light[1], light[2], 1.0);
  s.Renderer->WorldToDisplay();
  double lightPixel[3];
  s.Renderer->GetDisplayPoint(lightPixel);
  airtest::FloatImage edges = ref, nearLight = ref;
  size_t edgeCount = 0, nearCount = 0;
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      const size_t p = static_cast<size_t>(j) * W + i;
      bool edge = false;
      for (int k = 0; k < 4; ++k)
      {
        const int ni = i + (k == 0) - (k == 1), nj = j + (k == 2) - (k == 3);
        if (ni >= 0 && nj >= 0 && ni < W && nj < H)
        {
          const float a = plain.Depth[p], b = plain.Depth[static_cast<size_t>(nj) * W + ni];
          edge = edge || (a < 1.0f) != (b < 1.0f) || std::fabs(a - b) > 2e-3f;
        }
      }
      const bool near = std::hypot(i + 0.5 - lightPixel[0], j + 0.5 - lightPixel[1]) <= 12.0;
      edgeCount += edge;
      nearCount += near;
      for (int c = 0; c < 4; ++c)
      {
        if (!edge)
        {
          edges.RGBA[4 * p + c] = NAN;
        }
        if (!near)
        {
          nearLight.RGBA[4 * p + c] = NAN;
        }
      }
    }
  }
  std::cout << edgeCount << " depth-edge pixels, " << nearCount << " pixels near the light at (" << lightPixel[0]
            << ", " << lightPixel[1] << ")\n";
  PLUME_CHECK(edgeCount > 200);
  PLUME_CHECK(nearCount > 300);

  // Every spacing with one level, and the second level (spacing halved
  // inside refined cells: 8 -> 4, 4 -> 2).
  double onePixels = 0.0; // the refined pixels with one level, at this spacing
  double lattice8Max = 0.0; // D 8, one level: the largest difference from the per-pixel frame
  for (const std::pair<int, int> dl : std::vector<std::pair<int, int>>{
         { 1, 1 }, { 2, 1 }, { 4, 1 }, { 4, 2 }, { 8, 1 }, { 8, 2 } })
  {
    const int d = dl.first, levels = dl.second;
    s.Pass->SetDownsampling(d);
    s.Pass->SetLatticeLevels(levels);
    const airtest::FloatImage image = render(s);
    PLUME_CHECK(plume::test::GLErrors(s.Window).empty());
    const airtest::Error all = airtest::Compare(image, ref, air);
    const airtest::Error edge = airtest::Compare(image, edges, air);
    const airtest::Error near = airtest::Compare(image, nearLight, air);
    const airtest::Error vsFull = airtest::Compare(image, full, air);
    const double pixels = s.Pass->GetLastRefinedPixelFraction();
    std::cout << "downsampling " << d << ", " << levels << " level(s), refined cells "
              << s.Pass->GetLastRefinedCellFraction() << ", refined pixels " << pixels << ":\n";
    // the subsets' errors in units of the whole image's airlight range
    const double edgeMax = edge.Max * edge.Range / all.Range, nearMax = near.Max * near.Range / all.Range;
    airtest::Print("  all pixels", all);
    std::cout << "  depth edges: max " << 100 * edgeMax << " % (at " << edge.MaxX << ", " << edge.MaxY
              << "); near the light: max " << 100 * nearMax << " % (at " << near.MaxX << ", " << near.MaxY << ")\n";
    airtest::Print("  against the per-pixel pass", vsFull);
    airtest::Dump(image, "lattice " + std::to_string(d));
    PLUME_CHECK(all.Range > 0.9);
    PLUME_CHECK(all.RMS <= 0.005);
    PLUME_CHECK(all.Max <= 0.02);
    PLUME_CHECK(edgeMax <= 0.02);
    PLUME_CHECK(nearMax <= 0.02);
    if (d > 1)
    {
      // The lattice reproduces its nodes: at every node pixel (i D, j D, the
      // last row and column at the viewport's edge, where the last cell is
      // narrower) the frame is the per-pixel one, interpolated cell or not.
      double nodeMax = 0.0;
      const int cells[2] = { (W - 2) / d + 1, (H - 2) / d + 1 };
      for (int j = 0; j <= cells[1]; ++j)
      {
        for (int i = 0; i <= cells[0]; ++i)
        {
          const size_t p = static_cast<size_t>(std::min(j * d, H - 1)) * W + std::min(i * d, W - 1);
          for (int c = 0; c < 3; ++c)
          {
            nodeMax = std::max(nodeMax, static_cast<double>(std::fabs(image.RGBA[4 * p + c] - full.RGBA[4 * p + c])));
          }
        }
      }
      std::cout << "  at the nodes against the per-pixel pass: max " << nodeMax << "\n";
      PLUME_CHECK(nodeMax <= 1e-5);
      PLUME_CHECK(s.Pass->GetLastRefinedCellFraction() > 0.0);
      PLUME_CHECK(s.Pass->GetLastRefinedCellFraction() < 0.9);
      PLUME_CHECK(vsFull.Max > 1e-6); // some pixels really are interpolated
      PLUME_CHECK(pixels > 0.0);
    }
    if (levels == 1)
    {
      onePixels = pixels;
      lattice8Max = d == 8 ? vsFull.Max : lattice8Max;
    }
    else
    {
      // The second level interpolates a good part of the coarse refined cells
      // (here 49-54 % of their pixels; wrong level-1 nodes, e.g. another
      // node's value, only 23-31 %: their second differences refine more).
      PLUME_CHECK(pixels < 0.6 * onePixels);
    }
  }

  // The refined fractions count the lattice the last frame drew, also when
  // Downsampling changed after it (no frame since): the same as right after
  // it. (In the window: the pass keeps its textures, the flags are counted
  // when asked.)
  s.RenderAirlight();
  const double cells8 = s.Pass->GetLastRefinedCellFraction(), pixels8 = s.Pass->GetLastRefinedPixelFraction();
  PLUME_CHECK(cells8 > 0.0 && pixels8 > 0.0);
  s.RenderAirlight();
  s.Pass->SetDownsampling(2);
  std::cout << "in the window, downsampling 8, 2 levels: refined cells " << cells8 << ", refined pixels " << pixels8
            << "; counted after Downsampling 2 was set: " << s.Pass->GetLastRefinedCellFraction() << ", "
            << s.Pass->GetLastRefinedPixelFraction() << "\n";
  PLUME_CHECK(s.Pass->GetLastRefinedCellFraction() == cells8);
  PLUME_CHECK(s.Pass->GetLastRefinedPixelFraction() == pixels8);

  // Shadowed lights stay off the lattice: a thin pole's shadow shaft (about
  // 2 pixels wide here) can fall between nodes, where no classification rule
  // would see it. The default frame equals the per-pixel one.
  {
    // A pole narrower than a cell away from the lights' images (smooth
    // airlight): its pixels are the per-pixel ones, an absolute check (the
    // poles below are compared with the scene's own largest difference,
    // which grows with them if the depth rule is weakened everywhere).
    s.AddBox(-2.03, -1.97, 0.0, 3.0, 0.47, 0.53, 0.5, 0.5, 0.5);
    const airtest::FloatImage poled = s.RenderFloat(nullptr);
    s.Pass->SetDownsampling(1);
    const airtest::FloatImage poleFull = render(s);
    s.Pass->SetDownsampling(8);
    s.Pass->SetLatticeLevels(1);
    const airtest::FloatImage poleLattice = render(s);
    double poleMax = 0.0;
    size_t poleCount = 0;
    for (size_t p = 0; p < poled.Depth.size(); ++p)
    {
      if (poled.Depth[p] < plain.Depth[p])
      {
        ++poleCount;
        for (int c = 0; c < 3; ++c)
        {
          poleMax = std::max(poleMax, static_cast<double>(std::fabs(poleLattice.RGBA[4 * p + c] - poleFull.RGBA[4 * p + c])));
        }
      }
    }
    std::cout << "the pole's " << poleCount << " pixels against the per-pixel pass: max " << poleMax << "\n";
    PLUME_CHECK(poleCount > 100);
    PLUME_CHECK(poleMax <= 1e-5);
  }
  s.AddBox(1.4, 1.46, 0.0, 2.4, -1.6, -1.54, 0.5, 0.5, 0.5);
  // Unshadowed first, with a second thin pole near the camera, 2-3 cells
  // beside the point light's image: in front of the light's glow, its pixels
  // see only the haze up to it. Both poles (1-2 pixels wide) lie between the
  // nodes' columns, where no second difference sees them; they are nearer
  // than every corner of their cells, so the depth rules refine those (a
  // crease, where the depth only bends, may pass; a pole may not). Against
  // the per-pixel frame.
  s.AddBox(0.69, 0.705, 0.0, 2.6, 3.99, 4.01, 0.5, 0.5, 0.5);
  {
    s.Pass->SetDownsampling(1);
    s.Pass->SetLatticeLevels(1);
    const airtest::FloatImage poleFull = render(s);
    s.Pass->SetDownsampling(8);
    const airtest::Error pole = airtest::Compare(render(s), poleFull, air);
    airtest::Print("thin poles, downsampling 8, against the per-pixel pass", pole);
    // The poles add no error: the largest difference stays that of the
    // scene without them (0.15 %; with the poles' cells interpolated, 1.09 %).
    PLUME_CHECK(pole.Max <= 0.02);
    PLUME_CHECK(pole.Max <= 1.5 * lattice8Max);
  }
  s.Pass->ShadowsOn();
  s.Pass->SetDownsampling(1);
  const airtest::FloatImage shadowedFull = render(s);
  s.Pass->SetDownsampling(8);
  s.Pass->SetLatticeLevels(2);
  const airtest::FloatImage shadowed = render(s);
  const airtest::Error shadowedVsFull = airtest::Compare(shadowed, shadowedFull, air);
  airtest::Print("shadowed, default against every pixel", shadowedVsFull);
  PLUME_CHECK(shadowedVsFull.Max <= 1e-7);
  PLUME_CHECK(s.Pass->GetLastRefinedCellFraction() == 0.0);
  PLUME_CHECK(s.Pass->GetLastRefinedPixelFraction() == 0.0);
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
