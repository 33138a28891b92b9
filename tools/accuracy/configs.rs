// The accuracy study's configurations: one list, expanded by the study tool
// (`src/main.rs`, host) and by the emulated benchmark's `study` binary
// (`firmware/qemu-bench/src/bin/study.rs`), each defining `study_configs!`
// before including this file.
//
// (key, interpolation label, scalar, sub-pixel bits, perspective label,
//  perspective type, texture filter, per-pixel lighting, depth format)
study_configs! {
    ("fixed-6-span16-nearest-gouraud", "fixed 16.16", Fixed, 6, "every 16 px", PerSpan<16>, Nearest, false, Depth16),
    ("f32-6-span16-nearest-gouraud", "f32", f32, 6, "every 16 px", PerSpan<16>, Nearest, false, Depth16),
    ("fixed-0-span16-nearest-gouraud", "fixed 16.16", Fixed, 0, "every 16 px", PerSpan<16>, Nearest, false, Depth16),
    ("fixed-2-span16-nearest-gouraud", "fixed 16.16", Fixed, 2, "every 16 px", PerSpan<16>, Nearest, false, Depth16),
    ("fixed-4-span16-nearest-gouraud", "fixed 16.16", Fixed, 4, "every 16 px", PerSpan<16>, Nearest, false, Depth16),
    ("fixed-8-span16-nearest-gouraud", "fixed 16.16", Fixed, 8, "every 16 px", PerSpan<16>, Nearest, false, Depth16),
    ("fixed-6-affine-nearest-gouraud", "fixed 16.16", Fixed, 6, "affine", Affine, Nearest, false, Depth16),
    ("fixed-6-span8-nearest-gouraud", "fixed 16.16", Fixed, 6, "every 8 px", PerSpan<8>, Nearest, false, Depth16),
    ("fixed-6-span32-nearest-gouraud", "fixed 16.16", Fixed, 6, "every 32 px", PerSpan<32>, Nearest, false, Depth16),
    ("fixed-6-exact-nearest-gouraud", "fixed 16.16", Fixed, 6, "every pixel", PerPixel, Nearest, false, Depth16),
    ("f32-6-affine-nearest-gouraud", "f32", f32, 6, "affine", Affine, Nearest, false, Depth16),
    ("f32-6-span32-nearest-gouraud", "f32", f32, 6, "every 32 px", PerSpan<32>, Nearest, false, Depth16),
    ("f32-6-exact-nearest-gouraud", "f32", f32, 6, "every pixel", PerPixel, Nearest, false, Depth16),
    ("fixed-6-span16-bilinear-gouraud", "fixed 16.16", Fixed, 6, "every 16 px", PerSpan<16>, Bilinear, false, Depth16),
    ("fixed-6-span16-nearest-phong", "fixed 16.16", Fixed, 6, "every 16 px", PerSpan<16>, Nearest, true, Depth16),
    ("f32-6-span16-nearest-phong", "f32", f32, 6, "every 16 px", PerSpan<16>, Nearest, true, Depth16),
    ("fixed-6-affine-nearest-phong", "fixed 16.16", Fixed, 6, "affine", Affine, Nearest, true, Depth16),
    ("f32-8-exact-bilinear-phong", "f32", f32, 8, "every pixel", PerPixel, Bilinear, true, Depth16),
    ("fixed-8-exact-bilinear-gouraud", "fixed 16.16", Fixed, 8, "every pixel", PerPixel, Bilinear, false, Depth16),
    ("f32-6-span32-bilinear-gouraud", "f32", f32, 6, "every 32 px", PerSpan<32>, Bilinear, false, Depth16),
    ("fixed-6-span16-nearest-gouraud-d32", "fixed 16.16", Fixed, 6, "every 16 px", PerSpan<16>, Nearest, false, Depth32),
    ("f32-6-span16-nearest-gouraud-d32", "f32", f32, 6, "every 16 px", PerSpan<16>, Nearest, false, Depth32),
    ("f32-6-span16-nearest-gouraud-df32", "f32", f32, 6, "every 16 px", PerSpan<16>, Nearest, false, DepthF32),
}
