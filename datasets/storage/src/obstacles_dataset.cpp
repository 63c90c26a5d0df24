// The obstacles group of a run dataset (obstacles_dataset.hpp).
#include "obstacles_dataset.hpp"

#include <cstdint>
#include <string>

#include "hdf5_writing.hpp"

namespace wpg::datasets::detail {

// The scenario's obstacles as a table (one row per obstacle, in the scenario's order), so that
// plots and analyses need nothing but the file; outlines of boxes and polygons in one ragged
// vertex list.
void writeObstacles(GroupImage& run, const std::vector<Obstacle>& obstacles) {
  GroupImage& group = run.createGroup("obstacles");
  writeStringAttribute(group, "description",
                       "convex obstacles of the scenario (paper Sec. III-D), one row per obstacle "
                       "in the scenario's order; fields that do not apply to a type are 0");
  writeIntAttribute(group, "count", static_cast<int>(obstacles.size()));
  std::vector<std::uint8_t> types;
  std::vector<double> centers, radii, sizes, yaws, margins, vertices;
  std::vector<int> vertex_start, vertex_count;
  for (const Obstacle& obstacle : obstacles) {
    types.push_back(static_cast<std::uint8_t>(obstacle.type));
    centers.insert(centers.end(), {obstacle.center.x(), obstacle.center.y()});
    radii.push_back(obstacle.radius);
    sizes.insert(sizes.end(), {obstacle.size.x(), obstacle.size.y()});
    yaws.push_back(obstacle.yaw);
    margins.push_back(obstacle.margin);
    const std::vector<Eigen::Vector2d> outline = obstacle.worldVertices();
    vertex_start.push_back(static_cast<int>(vertices.size() / 2));
    vertex_count.push_back(static_cast<int>(outline.size()));
    for (const Eigen::Vector2d& v : outline) vertices.insert(vertices.end(), {v.x(), v.y()});
  }
  std::string codes;
  for (const ObstacleType type :
       {ObstacleType::kCircle, ObstacleType::kBox, ObstacleType::kPolygon}) {
    codes += (codes.empty() ? "" : ", ") + std::to_string(static_cast<int>(type)) + "=" +
             obstacleTypeName(type);
  }
  DatasetImage& type_set =
      writeCodes(group, "type", types,
                 {"1", nullptr, "shape of each obstacle, see the codes attribute", nullptr});
  writeStringAttribute(type_set, "codes", codes);
  writeDoubles(group, "center", centers, 2,
               {"m", "world", "centre of a circle or a box (0 for polygons)", "x, y"});
  writeDoubles(group, "radius", radii, 0, {"m", nullptr, "radius of a circle", nullptr});
  writeDoubles(
      group, "size", sizes, 2,
      {"m", nullptr, "length along the box's own x axis and width of a box", "length, width"});
  writeDoubles(group, "yaw", yaws, 0, {"rad", "world", "orientation of a box", nullptr});
  writeDoubles(
      group, "margin", margins, 0,
      {"m", nullptr,
       "security margin (eq. 18-19): the NMPC keeps step centres margin + the walking parameter "
       "obstacle_foot_radius away from the obstacle (walking.obstacle_distance_form: "
       "sole_clearance; paper: sqrt(radius^2 + margin^2) from a circle's centre, margin from "
       "other shapes)",
       nullptr});
  writeDoubles(group, "vertices", vertices, 2,
               {"m", "world",
                "outlines of the boxes and polygons, counter-clockwise, concatenated: rows "
                "vertex_start[i] to vertex_start[i] + vertex_count[i] - 1 belong to obstacle i",
                "x, y"});
  writeInts(group, "vertex_start", vertex_start,
            {"1", nullptr, "first row of each obstacle's outline in vertices", nullptr});
  writeInts(group, "vertex_count", vertex_count,
            {"1", nullptr, "rows of each obstacle's outline in vertices (0 for circles)", nullptr});
}

}  // namespace wpg::datasets::detail
