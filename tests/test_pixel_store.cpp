// The AVX2 kernels' pixel store (store_pixels_interleaved(), through store_group_interleaved(), in
// src/fill_span_writers.hpp): a batch's three channels written as packed
// three-float pixels, exactly the span's, none past it. The image tests
// compare whole pictures; this one checks every span length against
// untouched neighbours on both sides.
#include <array>
#include <vector>

#include <catch2/catch.hpp>

#include "fill_kernels_avx2.hpp"

using namespace phongrast;

namespace {

// Out of line and compiled for AVX2, as the kernels are (the store is always inlined).
__attribute__((target("avx2"), noinline)) void store_avx2(glm::vec3* pixels, int n,
                                                           const float (*channel)[detail::kSampleBatch]) {
    detail::avx2::store_pixels_interleaved(pixels, n, channel);
}

}  // namespace

TEST_CASE("the AVX2 pixel store writes exactly the span's pixels, each as its three channels") {
    if (!detail::kernel_isa_available(detail::KernelIsa::avx2)) {
        WARN("skipped: this build has no AVX2 kernels or this CPU has no AVX2 (the store is not used)");
        return;
    }
    float channel[3][detail::kSampleBatch];
    for (int c = 0; c < 3; ++c) {
        for (int l = 0; l < detail::kSampleBatch; ++l) channel[c][l] = static_cast<float>(100 * c + l) + 0.5f;
    }
    const glm::vec3 untouched(-1.0f, -2.0f, -3.0f);
    for (int offset = 0; offset < 3; ++offset) {  // the row's start need not be aligned to anything
        for (int n = 1; n <= detail::kSampleBatch; ++n) {
            std::vector<glm::vec3> row(detail::kSampleBatch + 8, untouched);
            store_avx2(row.data() + offset, n, channel);
            for (int i = 0; i < static_cast<int>(row.size()); ++i) {
                const int lane = i - offset;
                INFO("offset " << offset << ", span of " << n << ", pixel " << i);
                if (lane >= 0 && lane < n) {
                    CHECK(row[i] == glm::vec3(channel[0][lane], channel[1][lane], channel[2][lane]));
                } else {
                    CHECK(row[i] == untouched);
                }
            }
        }
    }
}
