//! Host side of the target benchmark: renders the benchmark scenes exactly
//! as `firmware/qemu-bench` does and prints `scene,mode,checksum` lines for
//! `scripts/target-bench.sh` to compare with the emulated Cortex-M.

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::RgbColor;
use soft3d::scenes::{demo_camera, demo_lights, draw_bench, FrameChecksum, BENCH_SCENES, DEMO_TRIANGLES, DEMO_VERTICES};
use soft3d::{HostRenderer, Settings};

fn run<S: Settings>(mode: &str) {
    let mut r: HostRenderer<Rgb565, 3, S> =
        HostRenderer::new(320, 240, 16, DEMO_VERTICES, DEMO_TRIANGLES, Rgb565::BLACK).expect("valid sizes");
    for (i, name) in BENCH_SCENES.iter().enumerate() {
        let mut frame = r.begin_frame(&demo_camera(), &demo_lights(), Rgb565::BLACK);
        draw_bench(&mut frame, i).expect("the scene fits its buffers");
        let mut sink = FrameChecksum::new(320, 240, Rgb565::BLACK);
        let Ok(_) = frame.finish(&mut sink);
        println!("{name},{mode},{:08x},{}", sink.sum, sink.drawn);
    }
}

fn main() {
    run::<soft3d::FixedPoint>("fixed");
    run::<soft3d::FloatingPoint>("f32");
}
