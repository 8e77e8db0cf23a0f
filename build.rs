//! Lists the string catalogue (`locales/<language>/*.ftl`) for `src/i18n`, so a
//! new file of messages needs no edit anywhere else.

use std::fmt::Write as _;
use std::path::Path;

fn main() {
    // Relative paths throughout: two checkouts sharing one target directory
    // share this script's output, and each must read its own files.
    println!("cargo:rerun-if-changed=locales");
    // Read at run time, not `env!`: a build script compiled for one checkout
    // is reused by another that shares the target directory.
    let manifest = std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR");
    let root = Path::new(&manifest).join("locales");
    let mut out = String::from("/// (language code, file name, contents), sorted.\n");
    out.push_str("pub const FILES: &[(&str, &str, &str)] = &[\n");
    let mut entries = Vec::new();
    for lang in std::fs::read_dir(&root).expect("locales/ is readable") {
        let lang = lang.expect("locales/ entry");
        if !lang.path().is_dir() {
            continue;
        }
        for file in std::fs::read_dir(lang.path()).expect("locales/<lang>/ is readable") {
            let path = file.expect("catalogue file").path();
            if path.extension().is_some_and(|e| e == "ftl") {
                let lang = lang.file_name().to_string_lossy().into_owned();
                let name = path
                    .file_name()
                    .expect("a file name")
                    .to_string_lossy()
                    .into_owned();
                println!("cargo:rerun-if-changed=locales/{lang}/{name}");
                let relative = format!("/locales/{lang}/{name}");
                entries.push((lang, name, relative));
            }
        }
    }
    entries.sort();
    for (lang, name, path) in entries {
        writeln!(
            out,
            "    ({lang:?}, {name:?}, include_str!(concat!(env!(\"CARGO_MANIFEST_DIR\"), {path:?}))),"
        )
            .expect("writing to a String");
    }
    out.push_str("];\n");
    let dest =
        Path::new(&std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("catalogue.rs");
    std::fs::write(dest, out).expect("OUT_DIR is writable");
}
