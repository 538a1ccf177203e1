// SPDX-License-Identifier: MIT
#include "drydem/analysis/chords.hpp"
#include <algorithm>

namespace drydem::analysis {

std::uint64_t ChordHistogram::chords() const {
    std::uint64_t n = 0;
    for (auto c : count) n += c;
    return n;
}

double ChordHistogram::mean_voxels() const {
    double n = 0.0, l = 0.0;
    for (std::size_t k = 0; k < count.size(); ++k) {
        n += double(count[k]);
        l += double(count[k]) * double(k);
    }
    return n > 0.0 ? l / n : 0.0;
}

double ChordHistogram::length_weighted_mean_voxels() const {
    double l = 0.0, l2 = 0.0;
    for (std::size_t k = 0; k < count.size(); ++k) {
        l += double(count[k]) * double(k);
        l2 += double(count[k]) * double(k) * double(k);
    }
    return l > 0.0 ? l2 / l : 0.0;
}

namespace {

void add(ChordHistogram& h, std::size_t n) {
    if (h.count.size() <= n) h.count.resize(n + 1, 0);
    ++h.count[n];
}

/// Runs of a periodic line of n samples read through `at`.
template <class At>
void periodic_runs(ChordHistogram& h, int n, At at) {
    int first_solid = -1;
    for (int q = 0; q < n; ++q)
        if (at(q) != label_pore) {
            first_solid = q;
            break;
        }
    if (first_solid < 0) {
        ++h.open_lines;
        return;
    }
    // Walk one period starting at a solid sample, so a run that wraps is seen whole.
    std::size_t run = 0;
    for (int s = 1; s <= n; ++s) {
        const int q = (first_solid + s) % n;
        if (at(q) == label_pore) {
            ++run;
        } else {
            if (run > 0) add(h, run);
            run = 0;
        }
    }
}

void merge(ChordHistogram& into, const ChordHistogram& from) {
    if (into.count.size() < from.count.size()) into.count.resize(from.count.size(), 0);
    for (std::size_t k = 0; k < from.count.size(); ++k) into.count[k] += from.count[k];
    into.open_lines += from.open_lines;
}

} // namespace

std::array<ChordHistogram, 3> chord_lengths(const VoxelGrid& g, int k_top) {
    k_top = std::clamp(k_top, 0, g.nz);
    std::array<ChordHistogram, 3> out;
#pragma omp parallel
    {
        std::array<ChordHistogram, 3> mine;
#pragma omp for schedule(static) nowait
        for (int k = 0; k < k_top; ++k) {
            for (int j = 0; j < g.ny; ++j) {
                const std::uint8_t* row = g.label.data() + g.index(0, j, k);
                periodic_runs(mine[0], g.nx, [row](int q) { return row[q]; });
            }
            for (int i = 0; i < g.nx; ++i) {
                const std::uint8_t* col = g.label.data() + g.index(i, 0, k);
                const std::size_t nx = std::size_t(g.nx);
                periodic_runs(mine[1], g.ny, [col, nx](int q) { return col[std::size_t(q) * nx]; });
            }
        }
        // z: a run from the substrate is bounded by the wall; one reaching k_top is cut.
#pragma omp for schedule(static) nowait
        for (int j = 0; j < g.ny; ++j) {
            std::vector<std::size_t> run(std::size_t(g.nx), 0); // per x, walked layer by layer
            for (int k = 0; k < k_top; ++k) {
                const std::uint8_t* row = g.label.data() + g.index(0, j, k);
                for (int i = 0; i < g.nx; ++i) {
                    std::size_t& r = run[std::size_t(i)];
                    if (row[i] == label_pore) {
                        ++r;
                    } else {
                        if (r > 0) add(mine[2], r);
                        r = 0;
                    }
                }
            }
            for (std::size_t r : run)
                if (r > 0) ++mine[2].open_lines;
        }
#pragma omp critical
        for (int a = 0; a < 3; ++a) merge(out[std::size_t(a)], mine[std::size_t(a)]);
    }
    return out;
}

} // namespace drydem::analysis
