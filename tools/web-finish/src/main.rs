//! `web-finish <dist>`: finishes a Trunk build of Shoal for the web.
//!
//! 1. Every `*_bg.wasm` loses its `name` custom section: function names, which
//!    only a debugger reads, about a tenth of the gzipped download. wasm-bindgen
//!    keeps it and Trunk has no setting to drop it.
//! 2. `index.html`'s `integrity="sha384-…"` of each changed file is recomputed,
//!    so the browser's check of the preloaded module still passes.
//! 3. Every wasm, JavaScript, HTML, CSS, SVG, JSON and manifest file gets a
//!    brotli (`.br`, quality 11) and a gzip (`.gz`, level 9) copy beside it, for
//!    servers that send precompressed files (nginx's `brotli_static` and
//!    `gzip_static`, Caddy's `precompressed`, tower-http's `ServeDir`).
//!
//! The sizes are printed, so a build log shows the download.

use base64::Engine as _;
use sha2::Digest as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};

fn main() {
    let Some(dir) = std::env::args_os().nth(1).map(PathBuf::from) else {
        eprintln!("usage: web-finish <dist folder>");
        std::process::exit(2);
    };
    if let Err(err) = finish(&dir) {
        eprintln!("web-finish: {err}");
        std::process::exit(1);
    }
}

fn finish(dir: &Path) -> Result<(), String> {
    let mut html = read_text(&dir.join("index.html"))?;
    for path in files(dir)? {
        let name = file_name(&path);
        if !name.ends_with("_bg.wasm") {
            continue;
        }
        let wasm = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        let stripped = without_custom_section(&wasm, "name")?;
        std::fs::write(&path, &stripped).map_err(|e| format!("{}: {e}", path.display()))?;
        html = with_integrity(&html, &name, &stripped);
        println!(
            "web-finish: {name}: {} → {} bytes without function names",
            wasm.len(),
            stripped.len()
        );
    }
    std::fs::write(dir.join("index.html"), &html).map_err(|e| format!("index.html: {e}"))?;
    for path in files(dir)? {
        if !compressible(&file_name(&path)) {
            continue;
        }
        let data = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        let br = brotli_bytes(&data)?;
        let gz = gzip_bytes(&data)?;
        if file_name(&path).ends_with(".wasm") {
            println!(
                "web-finish: {}: gzip {} bytes, brotli {} bytes",
                file_name(&path),
                gz.len(),
                br.len()
            );
        }
        std::fs::write(with_suffix(&path, ".br"), br).map_err(|e| e.to_string())?;
        std::fs::write(with_suffix(&path, ".gz"), gz).map_err(|e| e.to_string())?;
    }
    Ok(())
}

/// The files under `dir`, recursively, without earlier `.br`/`.gz` copies.
fn files(dir: &Path) -> Result<Vec<PathBuf>, String> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).map_err(|e| format!("{}: {e}", d.display()))? {
            let path = entry.map_err(|e| e.to_string())?.path();
            if path.is_dir() {
                stack.push(path);
            } else if !file_name(&path).ends_with(".br") && !file_name(&path).ends_with(".gz") {
                out.push(path);
            }
        }
    }
    out.sort();
    Ok(out)
}

fn file_name(path: &Path) -> String {
    path.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default()
}

fn with_suffix(path: &Path, suffix: &str) -> PathBuf {
    let mut s = path.as_os_str().to_owned();
    s.push(suffix);
    PathBuf::from(s)
}

fn read_text(path: &Path) -> Result<String, String> {
    std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))
}

fn compressible(name: &str) -> bool {
    [
        ".wasm",
        ".js",
        ".html",
        ".css",
        ".svg",
        ".json",
        ".webmanifest",
        ".txt",
    ]
    .iter()
    .any(|ext| name.ends_with(ext))
}

/// Reads an unsigned LEB128 number at `*at`, moving `*at` past it.
fn leb128(bytes: &[u8], at: &mut usize) -> Result<usize, String> {
    let mut value = 0usize;
    for shift in (0..35).step_by(7) {
        let byte = *bytes
            .get(*at)
            .ok_or("the wasm module ends inside a number")?;
        *at += 1;
        value |= usize::from(byte & 0x7f) << shift;
        if byte & 0x80 == 0 {
            return Ok(value);
        }
    }
    Err("a number in the wasm module is too long".into())
}

/// `wasm` without its custom sections called `section` (every other byte kept).
fn without_custom_section(wasm: &[u8], section: &str) -> Result<Vec<u8>, String> {
    if wasm.len() < 8 || &wasm[..4] != b"\0asm" {
        return Err("not a wasm module".into());
    }
    let mut out = wasm[..8].to_vec();
    let mut at = 8;
    while at < wasm.len() {
        let start = at;
        let id = wasm[at];
        at += 1;
        let size = leb128(wasm, &mut at)?;
        let end = at.checked_add(size).filter(|&e| e <= wasm.len());
        let end = end.ok_or("a wasm section runs past the end of the module")?;
        let drop = id == 0 && {
            let mut name_at = at;
            let len = leb128(wasm, &mut name_at)?;
            wasm.get(name_at..name_at + len) == Some(section.as_bytes())
        };
        if !drop {
            out.extend_from_slice(&wasm[start..end]);
        }
        at = end;
    }
    Ok(out)
}

/// `html` with the `integrity` of the tag that references `file` set to `data`'s
/// SHA-384 (Trunk writes `<link rel="preload" href="/file" … integrity="…">`).
fn with_integrity(html: &str, file: &str, data: &[u8]) -> String {
    let digest = sha2::Sha384::digest(data);
    let value = format!(
        "sha384-{}",
        base64::engine::general_purpose::STANDARD.encode(digest)
    );
    // Each piece from one `<` to the next holds one tag (Trunk writes several on
    // a line).
    html.split('<')
        .map(|tag| retag(tag, file, &value))
        .collect::<Vec<_>>()
        .join("<")
}

/// One tag with its integrity replaced, if it references `file`.
fn retag(tag: &str, file: &str, value: &str) -> String {
    const ATTR: &str = "integrity=\"";
    let end = tag.find('>').unwrap_or(tag.len());
    if !tag[..end].contains(&format!("/{file}\"")) && !tag[..end].contains(&format!("\"{file}\"")) {
        return tag.to_owned();
    }
    let Some(start) = tag[..end].find(ATTR).map(|i| i + ATTR.len()) else {
        return tag.to_owned();
    };
    let Some(len) = tag[start..end].find('"') else {
        return tag.to_owned();
    };
    format!("{}{value}{}", &tag[..start], &tag[start + len..])
}

fn brotli_bytes(data: &[u8]) -> Result<Vec<u8>, String> {
    let mut out = Vec::new();
    {
        let mut writer = brotli::CompressorWriter::new(&mut out, 1 << 16, 11, 22);
        writer.write_all(data).map_err(|e| e.to_string())?;
    }
    Ok(out)
}

fn gzip_bytes(data: &[u8]) -> Result<Vec<u8>, String> {
    let mut encoder = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
    encoder.write_all(data).map_err(|e| e.to_string())?;
    encoder.finish().map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A module of three sections: type (empty), a custom `name`, a custom `keep`.
    fn module() -> Vec<u8> {
        let mut m = b"\0asm\x01\0\0\0".to_vec();
        m.extend([1, 1, 0]); // type section, one byte: zero types
        m.extend([0, 7, 4]);
        m.extend(b"name");
        m.extend([1, 2]); // name section body
        m.extend([0, 6, 4]);
        m.extend(b"keep");
        m.extend([9]);
        m
    }

    #[test]
    fn only_the_named_custom_section_goes() {
        let m = module();
        let out = without_custom_section(&m, "name").expect("a module");
        assert_eq!(out.len(), m.len() - 9);
        assert!(out.windows(4).any(|w| w == b"keep"));
        assert!(!out.windows(4).any(|w| w == b"name"));
        assert_eq!(without_custom_section(&m, "absent").expect("a module"), m);
    }

    #[test]
    fn a_damaged_module_is_refused_not_cut() {
        let mut m = module();
        m.truncate(m.len() - 3);
        assert!(without_custom_section(&m, "name").is_err());
        assert!(without_custom_section(b"not wasm", "name").is_err());
    }

    #[test]
    fn the_integrity_of_the_changed_file_only_is_recomputed() {
        // As Trunk writes them: the module's and the wasm's tags on one line.
        let html = "<link rel=\"modulepreload\" href=\"/a.js\" integrity=\"sha384-KEEP\">\
                    <link rel=\"preload\" href=\"/a_bg.wasm\" integrity=\"sha384-OLD\" as=\"fetch\">\n";
        let out = with_integrity(html, "a_bg.wasm", b"abc");
        // SHA-384 of "abc" (FIPS 180-2's example), in base64.
        let expected = "sha384-ywB1P0WjXou1oD1pmsZQBycsMqsO3tFjGotgWkP/W+2AhgcroefMI1i67KE0yCWn";
        assert!(out.contains(expected), "{out}");
        assert!(out.contains("sha384-KEEP"));
        assert!(!out.contains("sha384-OLD"));
        assert!(out.contains("as=\"fetch\">"), "{out}");
        assert_eq!(out.matches(expected).count(), 1);
    }

    #[test]
    fn compressed_copies_decompress_to_the_file() {
        use std::io::Read as _;
        let data = b"Shoal Shoal Shoal Shoal Shoal Shoal".repeat(50);
        let gz = gzip_bytes(&data).expect("gzip");
        let mut back = Vec::new();
        flate2::read::GzDecoder::new(&gz[..])
            .read_to_end(&mut back)
            .expect("gunzip");
        assert_eq!(back, data);
        let br = brotli_bytes(&data).expect("brotli");
        let mut back = Vec::new();
        brotli::Decompressor::new(&br[..], 4096)
            .read_to_end(&mut back)
            .expect("unbrotli");
        assert_eq!(back, data);
        assert!(br.len() < data.len() / 10);
    }
}
