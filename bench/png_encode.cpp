// PNG encoding and decoding speed and size: phongrast's encoder (libdeflate,
// one fixed filter; src/io/png_encoder.cpp) at each --png-compression and a
// survey of levels and filters, against OpenImageIO's PNG writer (libpng with
// zlib level 6 and every filter tried on every row: what phongrast used
// before), and libspng's decoding against OpenImageIO's. Interleaved rounds,
// medians; bench/run_startup.sh runs it and docs/startup.md quotes it.
//
//   bench_png_encode [--rounds N] [--survey [--survey-filter none|sub|up|average|paeth] | --survey-split] IMAGE.png...
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <time.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include "image_decoders.hpp"
#include "phongrast/io/image_file.hpp"
#include "png_bytes.hpp"
#include "png_encoder.hpp"

using namespace phongrast;
namespace iod = phongrast::io::detail;

namespace {

double seconds_of(const std::function<void()>& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// CPU time of the whole process (every thread: the split encoder's second piece included).
double process_cpu_seconds() {
    timespec now{};
    ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

long file_size(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) return -1;
    std::fseek(file, 0, SEEK_END);
    const long size = std::ftell(file);
    std::fclose(file);
    return size;
}

/// OpenImageIO's PNG writer with its defaults, as phongrast's write_image called it before.
void write_with_openimageio(const std::string& path, const iod::PngPixels& pixels) {
    auto output = OIIO::ImageOutput::create(path);
    const OIIO::TypeDesc type = pixels.bit_depth == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8;
    OIIO::ImageSpec spec(pixels.columns, pixels.rows, pixels.channels, type);
    if (pixels.channels == 4) {
        spec.alpha_channel = 3;
        spec.attribute("oiio:UnassociatedAlpha", 1);
    }
    if (!output || !output->open(path, spec) || !output->write_image(type, pixels.data) || !output->close()) {
        throw std::runtime_error(path + ": OpenImageIO could not write");
    }
}

/// Whether the PNG's IHDR says 16-bit grey (bit depth at byte 24, colour type 0 at byte 25).
bool is_16_bit_grey_png(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    unsigned char header[26] = {};
    const bool read = file && std::fread(header, 1, sizeof header, file) == sizeof header;
    if (file) std::fclose(file);
    return read && header[24] == 16 && header[25] == 0;
}

struct Case {
    std::string name;
    std::function<void(const std::string& path)> write;
    std::vector<double> times;
    std::vector<double> cpu_times;
    long size = 0;
};

struct Variant {
    std::string name;
    iod::PngPixels pixels;
};

}  // namespace

int main(int argc, char** argv) {
    int rounds = 9;
    bool survey = false;
    std::string survey_filter;  // empty: all five
    bool survey_split = false;  // the survey of split images: zlib's level for the first rows x libdeflate's for the rest
    std::vector<std::string> inputs;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--rounds" && i + 1 < argc) {
            rounds = std::stoi(argv[++i]);
        } else if (argument == "--survey") {
            survey = true;
        } else if (argument == "--survey-split") {
            survey_split = true;
        } else if (argument == "--survey-filter" && i + 1 < argc) {
            survey_filter = argv[++i];
        } else {
            inputs.push_back(argument);
        }
    }
    const std::string scratch = "/tmp/phongrast-bench-png-" + std::to_string(::getpid());
    std::printf("| image | encoder | median ms | CPU ms | size bytes | time / OpenImageIO | size / OpenImageIO |\n|---|---|---|---|---|---|---|\n");
    for (const std::string& input : inputs) {
        const Image image = io::read_image(input);
        const std::string file_name = input.substr(input.find_last_of('/') + 1);
        const std::size_t count = image.pixels.size();
        std::vector<std::uint8_t> rgb(count * 3), rgba(count * 4);
        std::vector<std::uint16_t> rgb16(count * 3), grey16(count);
        for (std::size_t p = 0; p < count; ++p) {
            bool background = true;
            for (int c = 0; c < 3; ++c) {
                rgb[3 * p + c] = rgba[4 * p + c] = iod::to_8_bit(image.pixels[p][c]);
                rgb16[3 * p + c] = iod::to_16_bit(image.pixels[p][c]);
                background = background && rgb[3 * p + c] == 255;
            }
            rgba[4 * p + 3] = background ? 0 : 255;  // a transparent background, as --transparent writes
            grey16[p] = iod::to_16_bit(image.pixels[p][0]);  // k / 65535 back to k
        }
        // The survey covers each variant too: the default's level differs for 8-bit and 16-bit samples.
        // A 16-bit grey input (a dataset's NAME.depth.png, NAME.id.png) is
        // encoded as itself; a colour render as 8-bit RGB and RGBA and as
        // 16-bit RGB (what ImageWriteOptions::png_bit_depth = 16 writes).
        const std::vector<Variant> variants =
            is_16_bit_grey_png(input) ? std::vector<Variant>{{"grey 16-bit", {grey16.data(), image.columns, image.rows, 1, 16}}}
                                      : std::vector<Variant>{{"RGB 8-bit", {rgb.data(), image.columns, image.rows, 3, 8}},
                                                             {"RGBA 8-bit", {rgba.data(), image.columns, image.rows, 4, 8}},
                                                             {"RGB 16-bit", {rgb16.data(), image.columns, image.rows, 3, 16}}};
        for (const Variant& variant : variants) {
            std::vector<Case> cases;
            cases.push_back({"OpenImageIO (before)", [&](const std::string& path) { write_with_openimageio(path, variant.pixels); }, {}, {}, 0});
            const auto add = [&](const std::string& name, iod::PngSettings settings) {
                cases.push_back({name, [=](const std::string& path) { iod::write_png(path, path, variant.pixels, settings); }, {}, {}, 0});
            };
            if (survey_split) {
                for (int level : {2, 3, 4}) {
                    for (int head : {4, 5, 6}) {
                        add("zlib " + std::to_string(head) + " + libdeflate " + std::to_string(level) + ", up",
                            {level, iod::PngFilter::up, -1, head});
                    }
                }
            } else if (survey) {
                const char* filter_names[] = {"none", "sub", "up", "average", "paeth"};
                for (int filter = 0; filter < 5; ++filter) {
                    if (!survey_filter.empty() && survey_filter != filter_names[filter]) continue;
                    for (int level : {1, 2, 3, 4, 5, 6, 9, 12}) {
                        add("libdeflate " + std::to_string(level) + ", " + filter_names[filter],
                            {level, static_cast<iod::PngFilter>(filter)});
                    }
                }
            } else {
                for (io::PngCompression choice : {io::PngCompression::fast, io::PngCompression::standard, io::PngCompression::small}) {
                    add(std::string("phongrast --png-compression ") + io::to_string(choice), iod::png_settings(choice));
                }
            }
            for (int round = 0; round < rounds + 1; ++round) {
                for (std::size_t c = 0; c < cases.size(); ++c) {
                    const std::string path = scratch + "-" + std::to_string(c) + ".png";
                    const double cpu_before = process_cpu_seconds();
                    const double t = seconds_of([&] { cases[c].write(path); });
                    const double cpu = process_cpu_seconds() - cpu_before;
                    if (round > 0) {  // round 0 warms up
                        cases[c].times.push_back(t);
                        cases[c].cpu_times.push_back(cpu);
                    }
                    cases[c].size = file_size(path);
                    std::remove(path.c_str());
                }
            }
            const double base_time = median(cases[0].times);
            const double base_size = static_cast<double>(cases[0].size);
            for (const Case& c : cases) {
                std::printf("| %s %dx%d %s | %s | %.2f | %.2f | %ld | %.3f | %.3f |\n", file_name.c_str(),
                            image.columns, image.rows, variant.name.c_str(), c.name.c_str(), 1e3 * median(c.times),
                            1e3 * median(c.cpu_times), c.size,
                            median(c.times) / base_time, static_cast<double>(c.size) / base_size);
            }
        }
        if (!survey) {
            // Reading the file back: libspng (read_image) against OpenImageIO.
            std::vector<double> ours, theirs;
            for (int round = 0; round < rounds + 1; ++round) {
                const double a = seconds_of([&] { (void)io::read_image(input); });
                const double b = seconds_of([&] {
                    auto in = OIIO::ImageInput::open(input);
                    std::vector<float> values(count * static_cast<std::size_t>(in->spec().nchannels));
                    in->read_image(0, 0, 0, in->spec().nchannels, OIIO::TypeDesc::FLOAT, values.data());
                });
                if (round > 0) {
                    ours.push_back(a);
                    theirs.push_back(b);
                }
            }
            std::printf("| %s | read to float RGB: OpenImageIO | %.2f | | | 1.000 | |\n", file_name.c_str(), 1e3 * median(theirs));
            std::printf("| %s | read to float RGB: libspng (read_image) | %.2f | | | %.3f | |\n", file_name.c_str(),
                        1e3 * median(ours), median(ours) / median(theirs));
        }
    }
    return 0;
}
