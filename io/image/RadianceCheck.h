// A Radiance .hdr file (RGBE) checked through to its last scanline before
// stb_image decodes it: stb's run-length decoder loops forever on a count of
// zero, which is what it reads past the end of a truncated file, and reads
// zeros for missing flat pixels. Checked: the "#?RADIANCE" or "#?RGBE" magic,
// FORMAT=32-bit_rle_rgbe, the "-Y height +X width" resolution line (both
// ≥ 1; the orientation stb reads), then every scanline exactly as stb will
// read it — flat (4 bytes a pixel: widths below 8 or above 32767, or a first
// scanline without the 2, 2 marker) or new-style run-length (a 2, 2, width
// marker, then four channels of runs and dumps, each count ≥ 1 and within
// the width) — and refused with InputError naming the file and the first
// scanline that does not fit.
#pragma once

#include <string>
#include <string_view>

namespace eikon::io {

// True when `bytes` begin with the Radiance magic line.
bool isRadiance(std::string_view bytes);

void checkRadiance(std::string_view bytes, const std::string& path);

}  // namespace eikon::io
