//! # soft3d
//!
//! A `#![no_std]`, heap-free 3D software rasterizer for microcontroller
//! displays. It renders meshes that live in flash — flat, Gouraud or
//! vertex-color shaded, depth-tested, culled and clipped — into any
//! [`embedded_graphics`] `DrawTarget`, a few rows (a strip) at a time, so a
//! 320×240 frame needs a few kilobytes of buffer instead of 300.
//!
//! ```
//! use embedded_graphics::{mock_display::MockDisplay, pixelcolor::{Rgb565, Rgb888}, prelude::*};
//! use soft3d::{effect::Gouraud, math::{Mat4, Vec3}, mesh::MeshData, Camera, Lights, Material, Renderer};
//!
//! static CUBE: MeshData<24, 36> = MeshData::cube(1.0);
//! let mut renderer: Renderer<Rgb565, 64, 64, 8, 64, 64> = Renderer::new(Rgb565::BLACK);
//! let camera = Camera::looking_at(Vec3::new(1.5, 1.5, -3.0), Vec3::ZERO);
//! let material = Material::new(Gouraud).with_color(Rgb888::new(255, 160, 0));
//! let mut frame = renderer.begin_frame(&camera, &Lights::default(), Rgb565::BLACK);
//! frame.draw(&CUBE.mesh(), &Mat4::rotation_y(0.5), &material).unwrap();
//! let mut display = MockDisplay::new();
//! let stats = frame.finish(&mut display).unwrap();
//! assert_eq!(stats.queued, 6); // three faces visible, two triangles each
//! ```
//!
//! ## The pipeline, one module per stage
//! 1. [`mesh`]: static mesh data and generated shapes.
//! 2. [`vertex`]: transforms, normals, per-vertex lighting, projection.
//! 3. [`clip`]: bounding-sphere rejection, back-face culling in model space
//!    for meshes with face planes (before the vertex stage), near/far and
//!    guard-band clipping (culling by snapped winding happens at assembly in
//!    [`renderer`]).
//! 4. [`raster`]: snapping, exact top-left coverage, plane equations, span loops.
//! 5. [`renderer`]: frame buffers, binning, strips and output.
//!
//! Effects ([`effect`]) and materials ([`material`]) choose the span loop
//! at compile time; [`settings`] holds the numeric choices.
//!
//! ## Conventions
//! Left-handed world (x right, y up, z away from the viewer) as in Babylon;
//! window y down; pixel (x, y) is sampled at (x + 0.5, y + 0.5); coverage
//! follows the top-left rule; depth in [0, 1] with smaller nearer and a
//! "less" test; front faces are clockwise on screen.
#![no_std]
// One exemption: the FPU's square root (`math::elementary`), in `asm!`.
#![deny(unsafe_code)]
#![warn(missing_docs)]

#[cfg(any(feature = "std", test))]
extern crate std;
// Baked scenes name the crate `::soft3d`, wherever they are included.
extern crate self as soft3d;

#[cfg(feature = "babylon")]
pub mod babylon;
pub mod blend;
pub mod clip;
pub mod effect;
#[cfg(feature = "simulator")]
pub mod host;
pub mod material;
pub mod math;
pub mod mesh;
pub mod raster;
pub mod renderer;
pub mod scene;
pub mod scenes;
pub mod settings;
pub mod texture;
pub mod tri;
pub mod vertex;

pub use material::{Cull, Material};
pub use renderer::{DrawError, Frame, FrameStats, Renderer};
#[cfg(feature = "std")]
pub use renderer::{HostRenderer, SizeError};
pub use scene::{Camera, DirectionalLight, Lights, PointLight};
pub use settings::{Depth16, Depth32, DepthF32, DepthFormat, FixedPoint, FloatingPoint, Precision, Settings};

/// The README's examples are compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
