//! `soft3d-bake INPUT -o OUT.rs [options]`: bakes a `.babylon` or `.obj`
//! scene into Rust source. Exit status 0 on success, 1 when the input
//! cannot be baked, 2 on bad usage.

use soft3d_bake::{Options, Quantize, TextureFormat};
use std::path::PathBuf;
use std::process::ExitCode;

const USAGE: &str = "\
usage: soft3d-bake INPUT -o OUT.rs [options]

INPUT is a .babylon scene or a Wavefront .obj file (with its .mtl).

options:
  -o, --output FILE            the Rust source to write (required)
      --quantize f32|i16       vertex storage (default f32)
      --textures DIR           where texture files are (default: beside INPUT)
      --texture-format rgb565|palette8|none
                               texel storage (default rgb565); none skips textures
      --max-texture-size N     scale textures down to at most N texels a side
      --prefix NAME            prepend NAME_ to every generated item
      --face-planes            emit face planes (8 bytes a triangle): back faces
                               are then culled before the vertex stage
  -h, --help                   this text";

struct Args {
    input: PathBuf,
    output: PathBuf,
    options: Options,
}

fn parse(args: &[String]) -> Result<Option<Args>, String> {
    let mut input = None;
    let mut output = None;
    let mut options = Options::default();
    let mut i = 0;
    while i < args.len() {
        let arg = &args[i];
        i += 1;
        // `--flag=value` and `--flag value` are both accepted.
        let (flag, inline) = match arg.split_once('=') {
            Some((f, v)) if f.starts_with("--") => (f, Some(v.to_string())),
            _ => (arg.as_str(), None),
        };
        let takes_value =
            matches!(flag, "-o" | "--output" | "--quantize" | "--textures" | "--texture-format" | "--max-texture-size" | "--prefix");
        let value = if takes_value {
            match inline {
                Some(v) => v,
                None => {
                    let v = args.get(i).ok_or_else(|| format!("{flag} needs a value"))?;
                    i += 1;
                    v.clone()
                }
            }
        } else if inline.is_some() {
            return Err(format!("{flag} takes no value"));
        } else {
            String::new()
        };
        match flag {
            "-h" | "--help" => return Ok(None),
            "-o" | "--output" => output = Some(PathBuf::from(value)),
            "--quantize" => {
                options.quantize = match value.as_str() {
                    "f32" => Quantize::F32,
                    "i16" => Quantize::I16,
                    v => return Err(format!("--quantize takes f32 or i16, not '{v}'")),
                }
            }
            "--textures" => options.textures = Some(PathBuf::from(value)),
            "--texture-format" => {
                options.texture_format = match value.as_str() {
                    "rgb565" => TextureFormat::Rgb565,
                    "palette8" => TextureFormat::Palette8,
                    "none" => TextureFormat::None,
                    v => return Err(format!("--texture-format takes rgb565, palette8 or none, not '{v}'")),
                }
            }
            "--max-texture-size" => match value.parse::<u32>() {
                Ok(n) if n > 0 => options.max_texture_size = Some(n),
                _ => return Err(format!("--max-texture-size takes a positive number, not '{value}'")),
            },
            "--prefix" => options.prefix = value,
            "--face-planes" => options.face_planes = true,
            f if f.starts_with('-') && f.len() > 1 => return Err(format!("unknown option {f}")),
            _ => {
                if input.replace(PathBuf::from(arg)).is_some() {
                    return Err("only one INPUT can be given".into());
                }
            }
        }
    }
    let input = input.ok_or("no INPUT given")?;
    let output = output.ok_or("no output given (-o OUT.rs)")?;
    Ok(Some(Args { input, output, options }))
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let args = match parse(&args) {
        Ok(Some(a)) => a,
        Ok(None) => {
            println!("{USAGE}");
            return ExitCode::SUCCESS;
        }
        Err(e) => {
            eprintln!("soft3d-bake: {e}\n\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    match soft3d_bake::bake_file(&args.input, &args.output, &args.options) {
        Ok(report) => {
            for w in &report.warnings {
                eprintln!("warning: {w}");
            }
            println!("{report}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("soft3d-bake: error: {e}");
            ExitCode::from(1)
        }
    }
}
