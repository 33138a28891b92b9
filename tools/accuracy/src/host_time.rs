//! Host time per frame of each configuration and scene: read from the
//! root crate's criterion benchmark (`benches/study.rs`, ids
//! `study/<key>/<scene>`) and kept in a small CSV (`docs/accuracy/host.csv`)
//! so the report can be regenerated without timing again.
//!
//! Nothing here panics on bad input: unreadable files, malformed JSON and
//! malformed CSV lines are skipped.

use std::collections::BTreeMap;
use std::path::Path;

/// Times in nanoseconds per frame, by (configuration key, scene name).
pub type HostTimes = BTreeMap<(String, String), f64>;

/// Header line of the CSV file.
pub const CSV_HEADER: &str = "key,scene,ns_per_frame";

/// The criterion group of the benchmark.
const GROUP: &str = "study";

/// Reads the mean time per frame of every `study/<key>/<scene>` benchmark
/// under `dir` (the root crate's `target/criterion`), from
/// `<dir>/study/<key>/<scene>/new/estimates.json`, in nanoseconds.
/// Missing directories and unreadable or malformed files are skipped.
pub fn from_criterion(dir: &Path) -> HostTimes {
    let mut times = HostTimes::new();
    for (key, key_dir) in subdirectories(&dir.join(GROUP)) {
        for (scene, scene_dir) in subdirectories(&key_dir) {
            let Ok(json) = std::fs::read_to_string(scene_dir.join("new").join("estimates.json")) else {
                continue;
            };
            if let Some(ns) = mean_estimate(&json) {
                times.insert((key.clone(), scene), ns);
            }
        }
    }
    times
}

/// The subdirectories of `dir` with UTF-8 names, as (name, path); none if
/// `dir` cannot be read.
fn subdirectories(dir: &Path) -> Vec<(String, std::path::PathBuf)> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    entries
        .flatten()
        .filter(|e| e.file_type().is_ok_and(|t| t.is_dir()))
        .filter_map(|e| Some((e.file_name().into_string().ok()?, e.path())))
        .collect()
}

/// The point estimate of the mean in a criterion `estimates.json`
/// (`{"mean":{"confidence_interval":{…},"point_estimate":N,…},…}`): a
/// finite, non-negative number, or `None` if there is none.
fn mean_estimate(json: &str) -> Option<f64> {
    let mean = object_of(json, "mean")?;
    let value = number_of(mean, "point_estimate")?;
    (value.is_finite() && value >= 0.0).then_some(value)
}

/// The text after the first occurrence of `"name"` used as a key (followed
/// by `:`), with the whitespace after the colon trimmed.
fn after_key<'a>(json: &'a str, name: &str) -> Option<&'a str> {
    let quoted = format!("\"{name}\"");
    let mut rest = json;
    while let Some(at) = rest.find(&quoted) {
        rest = &rest[at + quoted.len()..];
        if let Some(value) = rest.trim_start().strip_prefix(':') {
            return Some(value.trim_start());
        }
    }
    None
}

/// The object (braces included) that key `name` holds, found by matching
/// braces outside strings.
fn object_of<'a>(json: &'a str, name: &str) -> Option<&'a str> {
    let value = after_key(json, name)?;
    if !value.starts_with('{') {
        return None;
    }
    let (mut depth, mut in_string, mut escaped) = (0usize, false, false);
    for (i, c) in value.char_indices() {
        if in_string {
            match c {
                _ if escaped => escaped = false,
                '\\' => escaped = true,
                '"' => in_string = false,
                _ => {}
            }
            continue;
        }
        match c {
            '"' => in_string = true,
            '{' => depth += 1,
            '}' => {
                depth = depth.checked_sub(1)?;
                if depth == 0 {
                    return Some(&value[..=i]);
                }
            }
            _ => {}
        }
    }
    None
}

/// The number that key `name` holds.
fn number_of(json: &str, name: &str) -> Option<f64> {
    let value = after_key(json, name)?;
    let end = value.find(|c: char| !(c.is_ascii_digit() || matches!(c, '-' | '+' | '.' | 'e' | 'E'))).unwrap_or(value.len());
    value[..end].parse().ok()
}

/// Writes `times` to `path` as CSV ([`CSV_HEADER`], then one line per
/// configuration and scene, in key order), creating its directory.
/// Refuses keys or scenes holding a comma or a line break, and times that
/// are not finite.
pub fn write_csv(path: &Path, times: &HostTimes) -> Result<(), String> {
    let mut text = format!("{CSV_HEADER}\n");
    for ((key, scene), ns) in times {
        if [key, scene].iter().any(|s| s.contains([',', '\n', '\r'])) {
            return Err(format!("{}: cannot write {key:?}/{scene:?} as CSV", path.display()));
        }
        if !ns.is_finite() {
            return Err(format!("{}: time of {key}/{scene} is {ns}", path.display()));
        }
        text.push_str(&format!("{key},{scene},{ns:.1}\n"));
    }
    if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
        std::fs::create_dir_all(parent).map_err(|e| format!("{}: {e}", parent.display()))?;
    }
    std::fs::write(path, text).map_err(|e| format!("{}: {e}", path.display()))
}

/// Reads a CSV written by [`write_csv`]: empty if the file is missing or
/// unreadable; the header, blank lines and malformed lines (not three
/// fields, an empty key or scene, a time that is not a finite
/// non-negative number) are skipped.
pub fn read_csv(path: &Path) -> HostTimes {
    let Ok(text) = std::fs::read_to_string(path) else {
        return HostTimes::new();
    };
    text.lines()
        .filter_map(|line| {
            let fields: Vec<&str> = line.trim().split(',').map(str::trim).collect();
            let [key, scene, ns] = fields[..] else {
                return None;
            };
            let ns: f64 = ns.parse().ok()?;
            let ok = !key.is_empty() && !scene.is_empty() && ns.is_finite() && ns >= 0.0;
            ok.then(|| ((key.to_string(), scene.to_string()), ns))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An `estimates.json` as criterion 0.7 writes it.
    const SAMPLE: &str = r#"{"mean":{"confidence_interval":{"confidence_level":0.95,"lower_bound":482962.9685185185,"upper_bound":582327.7294238682},"point_estimate":527621.5922545561,"standard_error":25724.412933045325},"median":{"confidence_interval":{"confidence_level":0.95,"lower_bound":479664.67680776014,"upper_bound":574428.9583333334},"point_estimate":505291.4166666667,"standard_error":20202.66754065906},"median_abs_dev":{"confidence_interval":{"confidence_level":0.95,"lower_bound":8873.2,"upper_bound":123422.9},"point_estimate":38362.6,"standard_error":29192.9},"slope":null,"std_dev":{"confidence_interval":{"confidence_level":0.95,"lower_bound":24109.0,"upper_bound":115733.0},"point_estimate":85819.5,"standard_error":24165.7}}"#;

    #[test]
    fn mean_from_estimates() {
        assert_eq!(mean_estimate(SAMPLE), Some(527621.5922545561));
        // Order and whitespace do not matter; the median is not the mean.
        let pretty = "{\n  \"median\": {\"point_estimate\": 1.0},\n  \"mean\" : { \"confidence_interval\": {\"lower_bound\": 2.0},\n \"point_estimate\" : 3.5e3 }\n}";
        assert_eq!(mean_estimate(pretty), Some(3500.0));
    }

    #[test]
    fn malformed_estimates_are_none() {
        for bad in [
            "",
            "{}",
            "not json",
            r#"{"mean":null}"#,
            r#"{"mean":{"point_estimate":"fast"}}"#,
            r#"{"mean":{"point_estimate":-1.0}}"#,
            r#"{"mean":{"confidence_interval":{"point_estimate":1.0}"#,
            r#"{"median":{"point_estimate":1.0}}"#,
        ] {
            assert_eq!(mean_estimate(bad), None, "{bad}");
        }
    }

    /// A fresh directory under the system's temporary directory.
    fn temp_dir(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("soft3d-host-time-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    #[test]
    fn reads_criterion_layout() {
        let dir = temp_dir("criterion");
        let put = |key: &str, scene: &str, json: &str| {
            let d = dir.join("study").join(key).join(scene).join("new");
            std::fs::create_dir_all(&d).expect("temp dir");
            std::fs::write(d.join("estimates.json"), json).expect("temp file");
        };
        put("fixed-6-span16-nearest-gouraud", "torus", SAMPLE);
        put("f32-6-span16-nearest-gouraud", "zfight", r#"{"mean":{"point_estimate":1000.5}}"#);
        put("f32-6-span16-nearest-gouraud", "floor", "garbage");
        let times = from_criterion(&dir);
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(times.len(), 2);
        assert_eq!(times.get(&("fixed-6-span16-nearest-gouraud".into(), "torus".into())), Some(&527621.5922545561));
        assert_eq!(times.get(&("f32-6-span16-nearest-gouraud".into(), "zfight".into())), Some(&1000.5));
        assert!(from_criterion(&dir).is_empty());
    }

    #[test]
    fn csv_round_trip() {
        let dir = temp_dir("csv");
        let path = dir.join("accuracy").join("host.csv");
        assert!(read_csv(&path).is_empty());
        let mut times = HostTimes::new();
        times.insert(("fixed-6-span16-nearest-gouraud".into(), "torus".into()), 527621.6);
        times.insert(("f32-6-exact-nearest-gouraud".into(), "floor".into()), 1_234_567.0);
        times.insert(("f32-6-exact-nearest-gouraud".into(), "zfight".into()), 0.5);
        write_csv(&path, &times).expect("writable temp file");
        let text = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(text.starts_with("key,scene,ns_per_frame\n"), "{text}");
        let back = read_csv(&path);
        assert_eq!(back.keys().collect::<Vec<_>>(), times.keys().collect::<Vec<_>>());
        for (k, v) in &times {
            assert!((back[k] - v).abs() < 0.05, "{k:?}: {} != {v}", back[k]);
        }

        // Malformed lines are skipped, the good ones kept.
        std::fs::write(&path, "key,scene,ns_per_frame\n\na,b\na,b,c\na,b,NaN\n,b,1\na,b,1,2\na,b,-3\n k , s , 42 \n").expect("temp file");
        let read = read_csv(&path);
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(read.len(), 1);
        assert_eq!(read.get(&("k".into(), "s".into())), Some(&42.0));

        // Keys that would break the file are refused.
        let mut bad = HostTimes::new();
        bad.insert(("a,b".into(), "c".into()), 1.0);
        assert!(write_csv(&dir.join("bad.csv"), &bad).is_err());
    }
}
