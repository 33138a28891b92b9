//! Huge and far triangles: vertices millions of pixels off screen,
//! triangles larger than the guard band, a screen-filling triangle with
//! its vertices far outside.
//!
//! The guard band: snapped coordinates must stay within ±2^(27 − 2·bits)
//! pixels (134,217,728 px at 0 bits, 8,388,608 at 2, 524,288 at 4, 32,768
//! at 6, 2,048 at 8; `soft3d::raster::guard`), so that the edge walkers
//! work in 32 bits and setup products fit 64. Inside it (the bound itself
//! included) coverage is exact: equal to the i128 oracle. A triangle with a
//! vertex beyond it is first clipped in f64 to ±(bound − 1) px and the new
//! vertices are snapped; each moves by at most half a sub-pixel per axis,
//! so a pixel may then differ from the oracle only if its center lies
//! within one sub-pixel of an edge of the original (snapped) triangle.
//! Debug builds check overflow, so every case also shows that nothing
//! overflows.

use crate::common::*;

const W: usize = 32;
const H: usize = 24;

/// The guard band at `bits`, in pixels.
fn guard_px(bits: u32) -> f64 {
    (1u64 << (27 - 2 * bits)) as f64
}

#[test]
fn vertices_millions_of_pixels_away_match_the_oracle() {
    for (bits, float) in MODES {
        let u = unit(bits);
        let g = guard_px(bits);
        let mut rng = Rng(0xfa4 + bits as u64);
        for n in 0..120 {
            // Up to 3 million pixels (and the guard band itself where it
            // is nearer), on the grid so the bound is reachable exactly.
            let far = [1e3, 1e5, 3e6, g][n % 4].min(g);
            let pts = if n % 2 == 0 {
                [0; 3].map(|_| (rng.grid(-far, far, u), rng.grid(-far, far, u)))
            } else {
                // An edge through a random on-screen point, so that the
                // far edge's exact position is what decides the pixels.
                let p = (rng.range(0.0, W as f64), rng.range(0.0, H as f64));
                let a = rng.range(0.0, std::f64::consts::TAU);
                let (dx, dy) = (a.cos() * far, a.sin() * far);
                let s = rng.range(0.05, 0.95);
                let on = |v: f64, lim: f64| ((v / u).round() * u).clamp(-lim, lim);
                [
                    (on(p.0 + dx * s, far), on(p.1 + dy * s, far)),
                    (on(p.0 - dx * (1.0 - s), far), on(p.1 - dy * (1.0 - s), far)),
                    (rng.grid(-far, far, u), rng.grid(-far, far, u)),
                ]
            };
            let want = oracle(&pts, W, H, bits);
            let got = coverage_mode(&[tri(&pts)], W, H, 8, bits, float);
            assert_eq!(got, want, "{} {pts:?}: {}", mode_name(bits, float), diff(&got, &want, W));
        }
    }
}

#[test]
fn vertices_exactly_at_the_guard_band_are_exact() {
    // The extremes of the 32-bit walkers: edges spanning the whole band
    // (2·bound wide or high), nearly horizontal and nearly vertical,
    // crossing the screen.
    for (bits, float) in MODES {
        let (u, g) = (unit(bits), guard_px(bits));
        let cases = [
            [(-g, -g), (g, -g), (-g, g)],
            [(g, g), (-g, g), (g, -g)],
            [(-g, 10.0), (g, 12.0 + u), (0.0, -g)], // shallow edge across the screen
            [(g, 11.0), (-g, 13.0), (5.0, g)],
            [(10.0, -g), (12.0 + u, g), (g, g)], // steep edge across the screen
            [(-g, -g), (g, g - u), (g, -g)],     // diagonal, one sub-pixel off
            [(-g, -g), (g, g), (-g, g - u)],
            [(16.0, 12.0), (g, g), (-g, g)],
        ];
        for pts in cases {
            let want = oracle(&pts, W, H, bits);
            for strip in [1, 7, H] {
                let got = coverage_mode(&[tri(&pts)], W, H, strip, bits, float);
                assert_eq!(got, want, "{} strip {strip} {pts:?}: {}", mode_name(bits, float), diff(&got, &want, W));
            }
        }
    }
}

/// Euclidean distance from `p` to the line through `a` and `b` (pixels).
fn distance_to_line(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    ((p.0 - a.0) * dy - (p.1 - a.1) * dx).abs() / (dx * dx + dy * dy).sqrt()
}

#[test]
fn triangles_beyond_the_guard_band_differ_only_within_a_subpixel_of_an_edge() {
    // (Moved from tests/coverage.rs, where it allowed any one pixel to
    // differ; now in every mode, with the bound stated above.)
    for (bits, float) in MODES {
        let (u, g) = (unit(bits), guard_px(bits));
        let mut rng = Rng(31337 + bits as u64);
        for n in 0..60 {
            let far = [1e9, 1e12, g * 4.0, g + 2.0 * u][n % 4];
            let pts = [
                (rng.grid(-far, far, 1.0), rng.grid(-far, far, 1.0)),
                (rng.grid(0.0, W as f64, u), rng.grid(0.0, H as f64, u)),
                (rng.grid(-far, far, u.max(far / 1e9)), rng.grid(-far, far, u.max(far / 1e9))),
            ];
            let want = oracle(&pts, W, H, bits);
            let got = coverage_mode(&[tri(&pts)], W, H, 8, bits, float);
            // The snapped original triangle, in pixels.
            let s: Vec<(f64, f64)> = pts.iter().map(|&(x, y)| (snap(x, bits) as f64 * u, snap(y, bits) as f64 * u)).collect();
            for (i, (a, b)) in got.iter().zip(&want).enumerate() {
                if a == b {
                    continue;
                }
                let c = ((i % W) as f64 + 0.5, (i / W) as f64 + 0.5);
                let d = (0..3).map(|k| distance_to_line(c, s[k], s[(k + 1) % 3])).fold(f64::MAX, f64::min);
                assert!(d <= u, "{} {pts:?}: pixel {c:?} differs {d} px from an edge: {}", mode_name(bits, float), diff(&got, &want, W));
            }
        }
    }
}

#[test]
fn a_screen_filling_triangle_with_far_vertices_covers_every_pixel_once() {
    // Inside the guard band, at it, and far beyond it (clipped first), in
    // both windings: the screen is far from every edge, so every pixel is
    // covered exactly once.
    for (bits, float) in MODES {
        let g = guard_px(bits);
        for far in [1e3, g / 2.0, g, 2.0 * g, 5e9, 1e12, 1e15] {
            for pts in [[(-far, -far), (far, -0.8 * far), (0.0, far)], [(-far, -far), (0.0, far), (far, -0.8 * far)]] {
                for strip in [1, 8, H] {
                    let got = coverage_mode(&[tri(&pts)], W, H, strip, bits, float);
                    assert!(
                        got.iter().all(|&c| c == 1),
                        "{} strip {strip} {pts:?}: {}",
                        mode_name(bits, float),
                        diff(&got, &[1; W * H], W)
                    );
                }
            }
        }
    }
}

#[test]
fn coordinates_at_and_past_every_limit_never_panic() {
    // (Moved from tests/coverage.rs and run in every mode.) Exactly at the
    // guard band, a sub-pixel either side of it, and at the ends of f64:
    // overflow checks are on, so any overflow would panic here; no pixel
    // is ever drawn twice by one triangle.
    for (bits, float) in MODES {
        let (u, g) = (unit(bits), guard_px(bits));
        let values = [0.0, 16.5, g, -g, g - u, g + u, -g - u, 1e12, -1e12, 1e300, -1e300, f64::MAX, f64::MIN, 1e-300];
        for &a in &values {
            for &b in &values {
                let got = coverage_mode(&[tri(&[(a, b), (b, 20.0), (10.0, a)])], 24, 24, 8, bits, float);
                assert!(got.iter().all(|&c| c <= 1), "{} ({a}, {b})", mode_name(bits, float));
            }
        }
        // Inside the guard band the result is still exact.
        let pts = [(-g + 1.0, -3.0), (g - 1.0, 5.5), (7.25, g - 1.0)];
        assert_eq!(coverage_mode(&[tri(&pts)], 24, 24, 8, bits, float), oracle(&pts, 24, 24, bits), "{}", mode_name(bits, float));
    }
}
