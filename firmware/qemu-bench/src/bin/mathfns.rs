//! Instructions per call of the elementary functions soft3d uses, from
//! each math backend (`libm`, `micromath`), measured in isolation on an
//! emulated Cortex-M: `mathfn,function,backend,core,instructions_per_call`.
//! `scripts/accuracy.sh` runs it on both cores; the study's "Math backend"
//! table reports the figures with each function's measured error.
//!
//! Each function runs over `INPUTS` (spanning the arguments the pipeline
//! passes it) `ROUNDS` times; the same loop with an identity function is
//! subtracted, so the figure is the call and the function alone. The `libm`
//! roots are soft3d's (`soft3d::math`), which on a core with an FPU use its
//! square root instruction; a `mathcheck` line first compares them with
//! libm's, bit for bit: `mathcheck,sqrt,core,arguments,differing`.
#![no_std]
#![no_main]

use core::hint::black_box;
use cortex_m_rt::entry;
use cortex_m_semihosting::hprintln;
use micromath::F32Ext;
use soft3d_qemu_bench::*;

/// Arguments: squared lengths for the roots (1e-4 to 1e4), angles for the
/// trigonometry (-4 to 4 radians), built without any elementary function.
fn inputs(trig: bool) -> [f32; INPUTS] {
    core::array::from_fn(|i| {
        let t = i as f32 / (INPUTS - 1) as f32;
        if trig {
            -4.0 + 8.0 * t
        } else {
            // Geometric from 1e-4 by a factor of 1e8 over the range.
            let mut v = 1e-4f32;
            for _ in 0..(i * 32 / INPUTS) {
                v *= 1.778_279_4; // 1e8^(1/32)
            }
            v * (1.0 + t)
        }
    })
}

const INPUTS: usize = 64;
const ROUNDS: usize = 16;

/// Instructions for `ROUNDS` passes of `f` over `xs`.
#[inline(never)]
fn run(timer: &mut Timer, xs: &[f32; INPUTS], f: fn(f32) -> f32) -> u32 {
    timer.start();
    let mut acc = 0.0f32;
    for _ in 0..ROUNDS {
        for &x in xs {
            acc += f(black_box(x));
        }
    }
    black_box(acc);
    timer.instructions().unwrap_or(0)
}

/// Compares soft3d's square root with libm's `sqrtf` over `2^18` arguments
/// spread over the whole `f32` range (every exponent, both signs, zero,
/// subnormals, infinities; any NaN matches any NaN) and prints how many
/// differ.
fn check_sqrt() {
    const ARGUMENTS: u32 = 1 << 18;
    let mut differing = 0u32;
    for i in 0..ARGUMENTS {
        // The top 18 bits step through the range; the low 14 come from a
        // multiplicative hash, so the rounding sees varied mantissas.
        let x = f32::from_bits((i << 14) | (i.wrapping_mul(0x9E37_79B9) >> 18));
        let (ours, libm) = (soft3d::math::sqrt(black_box(x)), libm::sqrtf(x));
        if ours.to_bits() != libm.to_bits() && !(ours.is_nan() && libm.is_nan()) {
            differing += 1;
        }
    }
    hprintln!("mathcheck,sqrt,{},{},{}", TARGET, ARGUMENTS, differing);
}

fn identity(x: f32) -> f32 {
    x
}

/// Prints one function's instructions per call, less the loop's own.
fn measure(timer: &mut Timer, name: &str, backend: &str, trig: bool, f: fn(f32) -> f32) {
    let xs = inputs(trig);
    let base = run(timer, &xs, identity);
    let total = run(timer, &xs, f);
    let per_call = (total.saturating_sub(base) as f32 / (INPUTS * ROUNDS) as f32 + 0.5) as u32;
    hprintln!("mathfn,{},{},{},{}", name, backend, TARGET, per_call);
}

#[entry]
fn main() -> ! {
    let mut timer = start_timer();
    check_sqrt();
    measure(&mut timer, "sqrt", "libm", false, soft3d::math::sqrt);
    measure(&mut timer, "sqrt", "micromath", false, F32Ext::sqrt);
    measure(&mut timer, "inverse sqrt", "libm", false, soft3d::math::rsqrt);
    measure(&mut timer, "inverse sqrt", "micromath", false, F32Ext::invsqrt);
    measure(&mut timer, "sin", "libm", true, libm::sinf);
    measure(&mut timer, "sin", "micromath", true, F32Ext::sin);
    measure(&mut timer, "cos", "libm", true, libm::cosf);
    measure(&mut timer, "cos", "micromath", true, F32Ext::cos);
    measure(&mut timer, "tan", "libm", true, |x| libm::tanf(x * 0.35));
    measure(&mut timer, "tan", "micromath", true, |x| F32Ext::tan(x * 0.35));
    exit()
}
