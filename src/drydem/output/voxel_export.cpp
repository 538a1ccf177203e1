// SPDX-License-Identifier: MIT
#include "drydem/output/voxel_export.hpp"
#include "drydem/core/error.hpp"
#include "drydem/io/particle_io.hpp"
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <tiffio.h>
#include <fstream>

namespace drydem {

namespace fs = std::filesystem;
using analysis::VoxelGrid;

VoxelExport write_voxel_image(const fs::path& dir, const VoxelGrid& g, const std::string& source,
                              bool tiff, const std::string& stem) {
    fs::create_directories(dir);
    VoxelExport e;
    e.raw = dir / (stem + ".raw");
    e.json = dir / (stem + ".json");
    e.mhd = dir / (stem + ".mhd");
    write_file_atomically(e.raw, [&](std::ostream& os) {
        os.write(reinterpret_cast<const char*>(g.label.data()), std::streamsize(g.label.size()));
    });
    nlohmann::ordered_json j;
    j["nx"] = g.nx;
    j["ny"] = g.ny;
    j["nz"] = g.nz;
    j["voxel_size_m"] = {g.ax, g.ay, g.az};
    j["dtype"] = "uint8";
    j["order"] = "x fastest, then y, then z (C order [z][y][x])";
    j["endianness"] = "little (1-byte values)";
    j["header_bytes"] = 0;
    j["labels"] = {
        {"0", "pore"}, {"1", "NCM (active material)"}, {"2", "carbon black agglomerate"}};
    j["origin_m"] = {0.0, 0.0, 0.0};
    j["voxel_centre"] = "(i + 1/2, j + 1/2, k + 1/2) times the voxel size; z = 0 is the substrate";
    j["periodic"] = {true, true, false};
    j["raw_file"] = e.raw.filename().string();
    j["source"] = source;
    write_file_atomically(e.json, [&](std::ostream& os) { os << j.dump(2) << "\n"; });
    write_file_atomically(e.mhd, [&](std::ostream& os) {
        os << "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
           << "CompressedData = False\n"
           << fmt::format("DimSize = {} {} {}\n", g.nx, g.ny, g.nz)
           << fmt::format("ElementSpacing = {:.9g} {:.9g} {:.9g}\n", g.ax * 1e6, g.ay * 1e6,
                          g.az * 1e6)
           << fmt::format("Offset = {:.9g} {:.9g} {:.9g}\n", 0.5 * g.ax * 1e6, 0.5 * g.ay * 1e6,
                          0.5 * g.az * 1e6)
           << "ElementType = MET_UCHAR\n"
           << "ElementDataFile = " << e.raw.filename().string() << "\n";
    });
    if (tiff) {
        e.tiff = dir / (stem + ".tif");
        const fs::path tmp = e.tiff.string() + ".tmp";
        TIFFSetWarningHandler(nullptr);
        // "w8": BigTIFF, so images over 4 GiB are fine.
        TIFF* t = TIFFOpen(tmp.c_str(), g.size() > (std::size_t(1) << 31) ? "w8" : "w");
        if (!t) throw RunError(fmt::format("cannot write {}", tmp.string()));
        for (int k = 0; k < g.nz; ++k) {
            TIFFSetField(t, TIFFTAG_IMAGEWIDTH, std::uint32_t(g.nx));
            TIFFSetField(t, TIFFTAG_IMAGELENGTH, std::uint32_t(g.ny));
            TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, 8);
            TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 1);
            TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
            TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
            TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
            TIFFSetField(t, TIFFTAG_ROWSPERSTRIP,
                         std::uint32_t(std::max(1, 65536 / std::max(1, g.nx))));
            TIFFSetField(t, TIFFTAG_SUBFILETYPE, FILETYPE_PAGE);
            TIFFSetField(t, TIFFTAG_PAGENUMBER, std::uint16_t(k), std::uint16_t(g.nz));
            TIFFSetField(t, TIFFTAG_RESOLUTIONUNIT, RESUNIT_CENTIMETER);
            TIFFSetField(t, TIFFTAG_XRESOLUTION, float(0.01 / g.ax));
            TIFFSetField(t, TIFFTAG_YRESOLUTION, float(0.01 / g.ay));
            TIFFSetField(
                t, TIFFTAG_IMAGEDESCRIPTION,
                fmt::format(
                    "DryDEM voxel labels 0 pore 1 NCM 2 CB; voxel {:.6g} um; z layer {} of {}",
                    g.az * 1e6, k, g.nz)
                    .c_str());
            for (int y = 0; y < g.ny; ++y) {
                auto* row = const_cast<std::uint8_t*>(g.label.data() + g.index(0, y, k));
                if (TIFFWriteScanline(t, row, std::uint32_t(y), 0) < 0) {
                    TIFFClose(t);
                    throw RunError(fmt::format("cannot write {}", tmp.string()));
                }
            }
            if (!TIFFWriteDirectory(t)) {
                TIFFClose(t);
                throw RunError(fmt::format("cannot write {}", tmp.string()));
            }
        }
        TIFFClose(t);
        fs::rename(tmp, e.tiff);
    }
    return e;
}

VoxelGrid read_voxel_image(const fs::path& json_file) {
    std::ifstream in(json_file);
    if (!in) throw InputError(fmt::format("cannot read {}", json_file.string()));
    nlohmann::json j;
    try {
        in >> j;
    } catch (const std::exception& ex) {
        throw InputError(fmt::format("{}: not JSON ({})", json_file.string(), ex.what()));
    }
    VoxelGrid g;
    g.nx = j.at("nx");
    g.ny = j.at("ny");
    g.nz = j.at("nz");
    g.ax = j.at("voxel_size_m")[0];
    g.ay = j.at("voxel_size_m")[1];
    g.az = j.at("voxel_size_m")[2];
    const fs::path raw = json_file.parent_path() / j.at("raw_file").get<std::string>();
    const std::size_t n = std::size_t(g.nx) * std::size_t(g.ny) * std::size_t(g.nz);
    if (!fs::exists(raw) || fs::file_size(raw) != n)
        throw InputError(
            fmt::format("{}: expected {} bytes ({} x {} x {})", raw.string(), n, g.nx, g.ny, g.nz));
    g.label.resize(n);
    std::ifstream r(raw, std::ios::binary);
    r.read(reinterpret_cast<char*>(g.label.data()), std::streamsize(n));
    return g;
}

VoxelGrid read_voxel_tiff(const fs::path& file) {
    TIFFSetWarningHandler(nullptr);
    TIFF* t = TIFFOpen(file.c_str(), "r");
    if (!t) throw InputError(fmt::format("cannot open TIFF {}", file.string()));
    VoxelGrid g;
    std::uint32_t w = 0, h = 0;
    TIFFGetField(t, TIFFTAG_IMAGEWIDTH, &w);
    TIFFGetField(t, TIFFTAG_IMAGELENGTH, &h);
    g.nx = int(w);
    g.ny = int(h);
    float xres = 0;
    if (TIFFGetField(t, TIFFTAG_XRESOLUTION, &xres) && xres > 0) g.ax = g.ay = g.az = 0.01 / xres;
    int k = 0;
    do {
        g.label.resize(std::size_t(k + 1) * w * h);
        for (std::uint32_t j = 0; j < h; ++j)
            if (TIFFReadScanline(t, g.label.data() + (std::size_t(k) * h + j) * w, j, 0) < 0) {
                TIFFClose(t);
                throw InputError(fmt::format("{}: unreadable page {}", file.string(), k));
            }
        ++k;
    } while (TIFFReadDirectory(t));
    TIFFClose(t);
    g.nz = k;
    return g;
}

} // namespace drydem
