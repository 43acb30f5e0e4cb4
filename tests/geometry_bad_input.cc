// SPDX-License-Identifier: GPL-3.0-or-later
//
// mesh_scene() refuses invalid geometry with a message that names the block
// or region, says what is wrong, gives the offending values and how to fix
// it. Every case below is one scene with one defect (next to a valid
// block, so that the message has to name the right one); the test checks
// that an exception is thrown and that its message contains the name and
// the key phrase, and prints the message. Two valid scenes (touching
// blocks, a block inside the hole of a region) must not throw.

#include <deal.II/base/exceptions.h>

#include <ndda/geometry/block_mesh.h>

#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "values.h"

using namespace ndda::geometry;
using dealii::Point;

namespace
{
  unsigned int n_failures = 0;
  // For doc/validation.md: geometries refused with a message that has
  // every phrase asked for (names of the block and of the fault), and valid
  // geometries accepted.
  unsigned int n_refused  = 0;
  unsigned int n_accepted = 0;

  std::vector<Point<2>>
  rectangle(const double x0, const double y0, const double x1, const double y1)
  {
    return {Point<2>(x0, y0),
            Point<2>(x1, y0),
            Point<2>(x1, y1),
            Point<2>(x0, y1)};
  }


  BlockDescription
  block(const std::string &name, const std::vector<Point<2>> &outer)
  {
    BlockDescription b;
    b.name      = name;
    b.outer     = outer;
    b.mesh_size = 0.5;
    return b;
  }


  /** A scene with a valid block "good" far away from everything else. */
  SceneGeometry
  scene_with(const BlockDescription &b)
  {
    SceneGeometry scene;
    scene.blocks = {block("good", rectangle(100, 100, 101, 101)), b};
    return scene;
  }


  SceneGeometry
  scene_with(const RegionDescription &r)
  {
    SceneGeometry scene;
    scene.blocks  = {block("good", rectangle(100, 100, 101, 101))};
    scene.regions = {r};
    return scene;
  }


  void
  expect_error(const std::string              &name,
               const SceneGeometry            &scene,
               const std::vector<std::string> &phrases)
  {
    std::string message;
    try
      {
        mesh_scene(scene);
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream s;
        e.print_info(s);
        message = s.str();
      }
    // print_info indents the message; drop the indentation.
    message.erase(0, message.find_first_not_of(" "));
    while (!message.empty() && message.back() == '\n')
      message.pop_back();
    std::cout << name << ": " << message << std::endl;
    if (message.empty())
      {
        std::cerr << "FAILED: " << name << ": no exception" << std::endl;
        ++n_failures;
        return;
      }
    bool complete = true;
    for (const auto &phrase : phrases)
      if (message.find(phrase) == std::string::npos)
        {
          std::cerr << "FAILED: " << name << ": the message lacks '" << phrase
                    << "'" << std::endl;
          ++n_failures;
          complete = false;
        }
    n_refused += complete ? 1 : 0;
  }


  void
  expect_success(const std::string &name, const SceneGeometry &scene)
  {
    try
      {
        const BlockMesh mesh = mesh_scene(scene);
        std::cout << name << ": accepted, " << mesh.block_names.size()
                  << " blocks" << std::endl;
        ++n_accepted;
      }
    catch (const std::exception &e)
      {
        std::cerr << "FAILED: " << name << ": " << e.what() << std::endl;
        ++n_failures;
      }
  }
} // namespace



int
main()
{
  expect_error(
    "two points",
    scene_with(
      block("sliver", {Point<2>(0, 0), Point<2>(1, 0), Point<2>(0, 0)})),
    {"Geometry: block 'sliver': ",
     "polygon is not closed: it needs at least three distinct points"});

  expect_error(
    "duplicate point",
    scene_with(block(
      "dup", {Point<2>(0, 0), Point<2>(1, 0), Point<2>(1, 0), Point<2>(1, 1)})),
    {"Geometry: block 'dup': ", "consecutive duplicate", "(1, 0)"});

  expect_error(
    "self-intersection",
    scene_with(
      block("bowtie",
            {Point<2>(0, 0), Point<2>(1, 1), Point<2>(1, 0), Point<2>(0, 1)})),
    {"Geometry: block 'bowtie': ", "self-intersecting", "(0.5, 0.5)"});

  expect_error(
    "zero area",
    scene_with(
      block("line",
            {Point<2>(0, 0), Point<2>(1, 0), Point<2>(2, 0), Point<2>(3, 0)})),
    {"Geometry: block 'line': ", "zero area"});

  {
    BlockDescription b = block("holey", rectangle(0, 0, 1, 1));
    b.holes            = {rectangle(0.5, 0.25, 1.5, 0.75)};
    expect_error("hole crossing the outer ring",
                 scene_with(b),
                 {"Geometry: block 'holey': ",
                  "hole 0 is not strictly inside the outer ring"});
    b.holes = {rectangle(2, 2, 3, 3)};
    expect_error("hole outside",
                 scene_with(b),
                 {"Geometry: block 'holey': ",
                  "hole 0 is not strictly inside the outer ring",
                  "(2, 2)"});
    b.holes = {rectangle(0.25, 0.25, 0.5, 0.5),
               rectangle(0.4, 0.4, 0.75, 0.75)};
    expect_error("overlapping holes",
                 scene_with(b),
                 {"Geometry: block 'holey': ", "holes 0 and 1 overlap"});
    b.holes = {rectangle(0.2, 0.2, 0.8, 0.8), rectangle(0.4, 0.4, 0.6, 0.6)};
    expect_error("hole in a hole",
                 scene_with(b),
                 {"Geometry: block 'holey': ", "holes 0 and 1 overlap"});
  }

  {
    BlockDescription b = block("cracky", rectangle(0, 0, 1, 1));
    b.cracks           = {{Point<2>(0.5, 0.5), Point<2>(1.5, 0.5)}};
    expect_error("crack leaving the block",
                 scene_with(b),
                 {"Geometry: block 'cracky': ",
                  "crack 0 from (0.5, 0.5) to (1.5, 0.5) is not inside the "
                  "block"});
    b.holes  = {rectangle(0.4, 0.4, 0.6, 0.6)};
    b.cracks = {{Point<2>(0.2, 0.5), Point<2>(0.8, 0.5)}};
    expect_error("crack through a hole",
                 scene_with(b),
                 {"Geometry: block 'cracky': ", "is not inside the block"});
    b.holes  = {};
    b.cracks = {{Point<2>(0, 0.2), Point<2>(0, 0.8)}};
    expect_error("crack along the boundary",
                 scene_with(b),
                 {"Geometry: block 'cracky': ",
                  "is not inside the block: it runs along the block "
                  "boundary"});
    b.cracks = {{Point<2>(0.5, 0.5), Point<2>(0.5, 0.5)}};
    expect_error("zero-length crack",
                 scene_with(b),
                 {"Geometry: block 'cracky': ", "zero length", "(0.5, 0.5)"});
  }

  {
    SceneGeometry scene = scene_with(block("left", rectangle(0, 0, 1, 1)));
    scene.blocks.push_back(block("right", rectangle(0.5, 0.5, 2, 2)));
    expect_error("overlapping blocks",
                 scene,
                 {"Geometry: block 'left': ", "overlaps block 'right'"});

    RegionDescription r;
    r.name      = "rock";
    r.outer     = rectangle(1.5, 0, 3, 1);
    r.mesh_size = 0.5;
    scene       = scene_with(r);
    scene.blocks.push_back(block("inside", rectangle(2, 0.2, 2.5, 0.8)));
    expect_error("block inside a region",
                 scene,
                 {"Geometry: block 'inside': ", "overlaps region 'rock'"});
  }

  {
    BlockDescription b = block("unsized", rectangle(0, 0, 1, 1));
    b.mesh_size        = 0.;
    b.target_n_cells   = 0;
    expect_error("no mesh size",
                 scene_with(b),
                 {"Geometry: block 'unsized': ",
                  "neither a mesh size nor a target number of cells"});
  }

  {
    RegionDescription r;
    r.name  = "twisted";
    r.outer = {Point<2>(0, 0), Point<2>(2, 2), Point<2>(2, 0), Point<2>(0, 2)};
    r.mesh_size = 0.5;
    expect_error(
      "self-intersecting region",
      scene_with(r),
      {"Geometry: region 'twisted': ", "self-intersecting", "(1, 1)"});
    r.name   = "jointed";
    r.outer  = rectangle(0, 0, 1, 1);
    r.joints = {{Point<2>(0.3, 0.3), Point<2>(0.3, 0.3)}};
    expect_error("zero-length joint",
                 scene_with(r),
                 {"Geometry: region 'jointed': ", "joint 0", "zero length"});
  }

  // Valid scenes.
  {
    SceneGeometry scene = scene_with(block("left", rectangle(0, 0, 1, 1)));
    scene.blocks.push_back(block("right", rectangle(1, 0.5, 2, 1.5)));
    scene.blocks.push_back(block("corner", rectangle(2, 1.5, 3, 2.5)));
    expect_success("touching blocks", scene);

    RegionDescription r;
    r.name      = "frame";
    r.outer     = rectangle(0, 0, 3, 3);
    r.holes     = {rectangle(1, 1, 2, 2)};
    r.joints    = {{Point<2>(-1, 1.5), Point<2>(4, 1.5)}};
    r.mesh_size = 0.5;
    scene       = scene_with(r);
    scene.blocks.push_back(block("core", rectangle(1, 1, 2, 2)));
    expect_success("block in the hole of a region", scene);
  }

  // Corners computed by trigonometry (Geometry/Snapping tolerance): a
  // block standing on a 30 degree incline, its base corners 2.0 and 2.3 m
  // up the slope, the incline a plain triangle. The corners lie a rounding
  // error off the slope; the overlap is a sliver that the tolerance takes
  // as touching, and that exact geometry (tolerance 0) refuses.
  {
    const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    const auto   on_slope = [&](const double d, const double up) {
      return Point<2>(d * c - up * s, d * s + up * c);
    };
    SceneGeometry scene;
    scene.blocks = {
      block("incline",
            {Point<2>(0, 0), Point<2>(5 * c, 0), Point<2>(5 * c, 5 * s)}),
      block("block",
            {on_slope(2.0, 0),
             on_slope(2.3, 0),
             on_slope(2.3, 1),
             on_slope(2.0, 1)})};
    expect_success("a block on an incline, corners by trigonometry", scene);
    scene.snap_tolerance = 0;
    expect_error("the same with Snapping tolerance = 0",
                 scene,
                 {"Geometry: block 'incline': ", "overlaps block 'block'"});
    // An overlap of 1e-6 of the scene's size is not a rounding error.
    scene.snap_tolerance = 1e-9;
    scene.blocks[1]      = block("block",
                            {on_slope(2.0, -1e-6),
                                  on_slope(2.3, -1e-6),
                                  on_slope(2.3, 1),
                                  on_slope(2.0, 1)});
    expect_error("a block sunk 1e-6 m into the incline",
                 scene,
                 {"Geometry: block 'incline': ", "overlaps block 'block'"});

    // Corners 1e-13 m apart become one point: the meshes of the two blocks
    // then share the corner's coordinates exactly.
    scene.blocks            = {block("left", rectangle(0, 0, 1, 1)),
                               block("right",
                          {Point<2>(1 + 1e-13, -1e-13),
                                      Point<2>(2, 0),
                                      Point<2>(2, 1),
                                      Point<2>(1, 1 + 1e-13)})};
    const BlockMesh mesh    = mesh_scene(scene);
    unsigned int    matched = 0;
    for (const auto &p : mesh.vertices)
      if (p == Point<2>(1, 0) || p == Point<2>(1, 1))
        ++matched;
    std::cout << "corners 1e-13 m apart: " << matched
              << " vertices at (1, 0) and (1, 1) (4: two per block)"
              << std::endl;
    if (matched != 4)
      {
        std::cerr << "FAILED: corners 1e-13 m apart were not snapped"
                  << std::endl;
        ++n_failures;
      }
  }

  ndda_tests::record("geometry_bad_input.refused", n_refused);
  ndda_tests::record("geometry_bad_input.accepted", n_accepted);
  std::cout << (n_failures == 0 ? "OK" : "FAILED") << std::endl;
  return n_failures == 0 ? 0 : 1;
}
