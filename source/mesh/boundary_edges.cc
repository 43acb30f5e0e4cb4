// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/exceptions.h>

#include <ndda/mesh/boundary_edges.h>

#include <algorithm>
#include <array>
#include <string>
#include <tuple>

namespace ndda
{
  std::vector<BoundaryEdge>
  boundary_edges(const geometry::BlockMesh &mesh)
  {
    // (min vertex, max vertex, triangle, local edge) for every edge of
    // every triangle; sorting brings the copies of an edge together.
    std::vector<std::array<unsigned int, 4>> all;
    all.reserve(3 * mesh.triangles.size());
    for (unsigned int t = 0; t < mesh.triangles.size(); ++t)
      for (unsigned int k = 0; k < 3; ++k)
        {
          const unsigned int a = mesh.triangles[t][k];
          const unsigned int b = mesh.triangles[t][(k + 1) % 3];
          all.push_back({{std::min(a, b), std::max(a, b), t, k}});
        }
    std::sort(all.begin(), all.end());

    std::vector<BoundaryEdge> edges;
    for (std::size_t i = 0; i < all.size();)
      {
        std::size_t j = i + 1;
        while (j < all.size() && all[j][0] == all[i][0] &&
               all[j][1] == all[i][1])
          ++j;
        AssertThrow(j - i <= 2,
                    dealii::ExcMessage(
                      "The edge between vertices " + std::to_string(all[i][0]) +
                      " and " + std::to_string(all[i][1]) + " is used by " +
                      std::to_string(j - i) + " triangles."));
        if (j - i == 1)
          {
            const unsigned int t = all[i][2];
            const unsigned int k = all[i][3];
            edges.push_back({mesh.triangles[t][k],
                             mesh.triangles[t][(k + 1) % 3],
                             mesh.cell_block.empty() ? 0u : mesh.cell_block[t],
                             t,
                             k});
          }
        i = j;
      }
    std::sort(edges.begin(),
              edges.end(),
              [](const BoundaryEdge &a, const BoundaryEdge &b) {
                return std::tie(a.v0, a.v1) < std::tie(b.v0, b.v1);
              });
    return edges;
  }
} // namespace ndda
