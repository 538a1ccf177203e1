// SPDX-License-Identifier: MIT
// Voxel image export (docs/analysis.md "Files"): `structure.raw` (uint8 labels 0 pore / 1 NCM / 2 CB, x fastest
// then y then z, no header), `structure.json` (sidecar: sizes, voxel size, order, labels, origin,
// source), `structure.mhd` (MetaImage header pointing at the raw: ParaView, Fiji/ImageJ, ITK,
// GeoDict's raw import) and optionally `structure.tif` (multi-page, one page per z layer, deflate).
//
// numpy / PoreSpy:  im = np.fromfile("structure.raw", np.uint8).reshape(nz, ny, nx)
//                   pores = (im == 0).transpose(2, 1, 0)   # x, y, z order, True = pore
#pragma once
#include "drydem/analysis/voxel_grid.hpp"
#include <filesystem>
#include <string>

namespace drydem {

struct VoxelExport {
    std::filesystem::path raw, json, mhd, tiff; ///< tiff empty when not written
};

/// Writes the files into `dir` with the base name `stem`; `source` names the particle file.
VoxelExport write_voxel_image(const std::filesystem::path& dir, const analysis::VoxelGrid& g,
                              const std::string& source, bool tiff,
                              const std::string& stem = "structure");

/// Reads a voxel image back from its JSON sidecar (labels and geometry); RunError/InputError on a
/// file that does not match its sidecar.
[[nodiscard]] analysis::VoxelGrid read_voxel_image(const std::filesystem::path& json);

/// Reads a multi-page TIFF written by write_voxel_image (for tests and round trips).
[[nodiscard]] analysis::VoxelGrid read_voxel_tiff(const std::filesystem::path& tiff);

} // namespace drydem
