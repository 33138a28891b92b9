//! Category 9, textures: coordinates negative, exactly 1, 1e6; 1×1 and
//! non-square textures; bilinear filtering at the border with repeat and
//! clamp. A screen-aligned quad with w = 1 puts texel boundaries on known
//! pixels, so each case has an exact expected image.

use super::depth::{all_modes, mode};
use embedded_graphics::pixelcolor::IntoStorage;
use soft3d::texture::{Bilinear, Clamp, Filter, Nearest, Repeat, Texture, TextureError, Wrap};
use soft3d::Settings;

const WHITE: u16 = 0xFFFF;
const BLACK: u16 = 0x0000;

/// The quad `[-1, 1]²` at z = 0 filling a `size`×`size` image (clip space
/// = model space, w = 1), with coordinates `uv0` at the top left and `uv1`
/// at the bottom right, unlit.
fn render<S: Settings, F: Filter, W: Wrap>(texture: Texture<'_>, uv0: (f32, f32), uv1: (f32, f32), size: usize) -> Vec<u16> {
    let img = crate::common::render_textured_quad::<S, F, W>(texture, uv0, uv1, size);
    img.pixels.iter().map(|c| c.into_storage()).collect()
}

/// A 4×4 texture whose texels all differ.
fn distinct() -> Vec<u16> {
    (0..16u16).map(|i| (i << 11) | ((i * 3) << 5) | (31 - i)).collect()
}

#[test]
fn negative_huge_and_past_one_coordinates_repeat_like_zero_to_one() {
    // The quad maps [u0, u0 + 1] × [v0, v0 + 1]: with a true modulo every
    // start gives the 0-to-1 image, texel for texel (8×8 pixels each).
    fn case<S: Settings>() {
        let texels = distinct();
        let tex = Texture::new(&texels, 4, 4).unwrap();
        let want: Vec<u16> = (0..32 * 32).map(|i| texels[(i / 32 / 8) * 4 + (i % 32) / 8]).collect();
        let starts = [(0.0, 0.0), (1.0, 1.0), (-1.0, -1.0), (-3.0, -7.0), (-1.0, 2.0), (5.0, 1.0), (1.0e6, -1.0e6), (4096.0, 65536.0)];
        for (u0, v0) in starts {
            let got = render::<S, Nearest, Repeat>(tex, (u0, v0), (u0 + 1.0, v0 + 1.0), 32);
            assert_eq!(got, want, "{} uv from ({u0}, {v0})", mode::<S>());
        }
    }
    all_modes!(case);
}

#[test]
fn constant_coordinates_at_one_and_beyond_pick_the_wrapped_or_edge_texel() {
    // Every vertex at the same (u, v): Repeat shows texel (u mod 1, v mod 1),
    // here always (0, 0); Clamp the nearest edge texel. Bilinear at a texel
    // corner averages the four texels around it (rounded half up).
    fn case<S: Settings>() {
        let texels = distinct();
        let tex = Texture::new(&texels, 4, 4).unwrap();
        let avg = |ids: [usize; 4]| {
            let ch = |shift: u32, mask: u16| {
                let sum: u32 = ids.iter().map(|&i| ((texels[i] >> shift) & mask) as u32).sum();
                (((sum as f64 / 4.0) + 0.5).floor() as u16) << shift
            };
            ch(11, 0x1F) | ch(5, 0x3F) | ch(0, 0x1F)
        };
        for (u, v, clamped) in [(1.0, 1.0, 15), (1.0e6, 1.0e6, 15), (-3.0, 5.0, 12), (0.0, 1.0, 12), (2.0, -1.0e6, 3)] {
            let uv = (u, v);
            let all = |px: &[u16], want: u16, what: &str| {
                assert!(px.iter().all(|&p| p == want), "{} {what} at ({u}, {v}): {:04x} vs {want:04x}", mode::<S>(), px[0]);
            };
            all(&render::<S, Nearest, Repeat>(tex, uv, uv, 8), texels[0], "nearest repeat");
            all(&render::<S, Nearest, Clamp>(tex, uv, uv, 8), texels[clamped], "nearest clamp");
            // Bilinear repeat at a corner: texels (3, 3), (0, 3), (3, 0), (0, 0).
            all(&render::<S, Bilinear, Repeat>(tex, uv, uv, 8), avg([15, 12, 3, 0]), "bilinear repeat");
            all(&render::<S, Bilinear, Clamp>(tex, uv, uv, 8), texels[clamped], "bilinear clamp");
        }
    }
    all_modes!(case);
}

#[test]
fn clamp_repeats_the_edge_texels() {
    // u and v from -1 to 2: the middle third shows the texture (4 pixels a
    // texel), the rest its edge texels.
    fn case<S: Settings>() {
        let texels = distinct();
        let tex = Texture::new(&texels, 4, 4).unwrap();
        let got = render::<S, Nearest, Clamp>(tex, (-1.0, -1.0), (2.0, 2.0), 48);
        for y in 0..48usize {
            for x in 0..48usize {
                let tx = (x as i32 / 4 - 4).clamp(0, 3) as usize;
                let ty = (y as i32 / 4 - 4).clamp(0, 3) as usize;
                assert_eq!(got[y * 48 + x], texels[ty * 4 + tx], "{} pixel {x},{y}", mode::<S>());
            }
        }
    }
    all_modes!(case);
}

#[test]
fn one_texel_and_non_square_textures() {
    fn case<S: Settings>() {
        let m = mode::<S>();
        // 1×1: that texel everywhere, whatever the filter, wrap or coordinates.
        let one = [0xF800u16];
        let tex = Texture::new(&one, 1, 1).unwrap();
        let (a, b) = ((-2.5, 0.3), (7.0, 1e4));
        for px in [
            render::<S, Nearest, Repeat>(tex, a, b, 16),
            render::<S, Nearest, Clamp>(tex, a, b, 16),
            render::<S, Bilinear, Repeat>(tex, a, b, 16),
            render::<S, Bilinear, Clamp>(tex, a, b, 16),
        ] {
            assert!(px.iter().all(|&p| p == 0xF800), "{m} 1×1");
        }
        // 8×1 (white left half) and 1×8 (white top half): 2 pixels a texel.
        let half: Vec<u16> = (0..8).map(|i| if i < 4 { WHITE } else { BLACK }).collect();
        let wide = render::<S, Nearest, Repeat>(Texture::new(&half, 8, 1).unwrap(), (0.0, 0.0), (1.0, 1.0), 16);
        let tall = render::<S, Nearest, Repeat>(Texture::new(&half, 1, 8).unwrap(), (0.0, 0.0), (1.0, 1.0), 16);
        for y in 0..16 {
            for x in 0..16 {
                assert_eq!(wide[y * 16 + x], if x < 8 { WHITE } else { BLACK }, "{m} 8×1 at {x},{y}");
                assert_eq!(tall[y * 16 + x], if y < 8 { WHITE } else { BLACK }, "{m} 1×8 at {x},{y}");
            }
        }
        // 4×2, repeated twice across and down: 4 pixels wide, 8 tall a texel.
        let texels = &distinct()[..8];
        let got = render::<S, Nearest, Repeat>(Texture::new(texels, 4, 2).unwrap(), (-1.0, 3.0), (1.0, 5.0), 32);
        for y in 0..32 {
            for x in 0..32 {
                assert_eq!(got[y * 32 + x], texels[(y / 8 % 2) * 4 + x / 4 % 4], "{m} 4×2 at {x},{y}");
            }
        }
    }
    all_modes!(case);
    let half = [WHITE; 8];
    assert_eq!(Texture::new(&half, 6, 1).unwrap_err(), TextureError::Size { width: 6, height: 1 });
    assert_eq!(Texture::new(&half, 4, 1).unwrap_err(), TextureError::Length { expected: 4, found: 8 });
    assert_eq!(Texture::new(&half, 0, 8).unwrap_err(), TextureError::Size { width: 0, height: 8 });
}

#[test]
fn bilinear_blends_across_the_border_when_repeating_and_not_when_clamping() {
    // Two texels, white then black, over 64 pixels: pixel x samples
    // u = (x + 0.5) / 32 texels. Reference in f64 with the 8-bit weights
    // the filter uses: white weight w at the offset from the white center.
    fn case<S: Settings>() {
        let texels = [WHITE, BLACK];
        let tex = Texture::new(&texels, 2, 1).unwrap();
        let repeat = render::<S, Bilinear, Repeat>(tex, (0.0, 0.0), (1.0, 1.0), 64);
        let clamp = render::<S, Bilinear, Clamp>(tex, (0.0, 0.0), (1.0, 1.0), 64);
        let red = |p: u16| (p >> 11) as i32;
        for x in 0..64 {
            let u = (x as f64 + 0.5) / 32.0 - 0.5; // from the white texel's center
            let frac = u - u.floor(); // weight of the texel to the right
            let white_right = u.floor().rem_euclid(2.0) == 1.0;
            let white = if white_right { frac } else { 1.0 - frac };
            let want_repeat = (31.0 * white).round() as i32;
            let want_clamp = (31.0 * (1.0 - u.clamp(0.0, 1.0))).round() as i32;
            let (r, c) = (red(repeat[5 * 64 + x]), red(clamp[5 * 64 + x]));
            let m = mode::<S>();
            assert!((r - want_repeat).abs() <= 1, "{m} repeat x {x}: {r} vs {want_repeat}");
            assert!((c - want_clamp).abs() <= 1, "{m} clamp x {x}: {c} vs {want_clamp}");
        }
        // Exactly at the borders: clamped edges are pure, repeated ones
        // are half blends (pixel 0 is a quarter texel left of white's center).
        assert_eq!((red(clamp[5 * 64]), red(clamp[5 * 64 + 63])), (31, 0));
        assert!((red(repeat[5 * 64]) - 16).abs() <= 1 && (red(repeat[5 * 64 + 63]) - 15).abs() <= 1);
    }
    all_modes!(case);
}
