//! Where each input's output goes when a run writes to a directory: the mirror of the input tree.
//!
//! Rule: the output of an input is `OUTDIR/<relative path>` with the extension replaced by the
//! output format's (`shapes/a/b.wkt` found under `shapes/` → `OUTDIR/a/b.json`). When several
//! inputs would get the same output (`a.wkt` and `a.geojson`), or an output would be an input
//! file itself (`a.json` read from the output directory), each of those keeps its whole file
//! name and gets the extension appended (`a.wkt.json`, `a.geojson.json`). Should two outputs
//! still coincide (the same relative path under two directory inputs), the first input keeps it
//! and the others get an error instead of an output: nothing is ever silently overwritten.
//!
//! Paths are compared as written after [`std::path::absolute`] (symbolic links are not
//! resolved). Complexity: O(k log k) for k inputs.

use super::discover::Input;
use std::collections::HashMap;
use std::ffi::OsString;
use std::path::{Path, PathBuf};

/// The output file of each input (aligned with `inputs`), or why it gets none.
///
/// # Examples
/// ```
/// use minitri::batch::{plan, Input};
/// use std::path::PathBuf;
/// let input = |p: &str, r: &str| Input { path: p.into(), relative: r.into(), walked: true };
/// let inputs = [input("in/a.wkt", "a.wkt"), input("in/a.geojson", "a.geojson"), input("in/d/b.txt", "d/b.txt")];
/// let outputs = plan(&inputs, "out".as_ref(), "json");
/// assert_eq!(outputs[0], Ok(PathBuf::from("out/a.wkt.json")));
/// assert_eq!(outputs[1], Ok(PathBuf::from("out/a.geojson.json")));
/// assert_eq!(outputs[2], Ok(PathBuf::from("out/d/b.json")));
/// ```
pub fn plan(inputs: &[Input], out_dir: &Path, extension: &str) -> Vec<Result<PathBuf, String>> {
    let absolute = |p: &Path| std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf());
    let input_paths: Vec<PathBuf> = inputs.iter().map(|i| absolute(&i.path)).collect();
    let replaced: Vec<PathBuf> = inputs
        .iter()
        .map(|i| out_dir.join(i.relative.with_extension(extension)))
        .collect();
    let mut uses: HashMap<PathBuf, usize> = HashMap::new();
    for target in &replaced {
        *uses.entry(absolute(target)).or_default() += 1;
    }
    let targets: Vec<PathBuf> = inputs
        .iter()
        .zip(&replaced)
        .map(|(input, target)| {
            let key = absolute(target);
            if uses[&key] > 1 || input_paths.contains(&key) {
                let mut name = OsString::from(input.relative.as_os_str());
                name.push(".");
                name.push(extension);
                out_dir.join(name)
            } else {
                target.clone()
            }
        })
        .collect();
    let mut first: HashMap<PathBuf, usize> = HashMap::new();
    targets
        .into_iter()
        .enumerate()
        .map(|(k, target)| {
            let key = absolute(&target);
            if input_paths.contains(&key) {
                return Err(format!(
                    "not processed: its output {} would overwrite an input",
                    target.display()
                ));
            }
            match first.get(&key) {
                Some(&j) => Err(format!(
                    "not processed: its output {} would overwrite the output of {}",
                    target.display(),
                    inputs[j].path.display()
                )),
                None => {
                    first.insert(key, k);
                    Ok(target)
                }
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(path: &str, relative: &str) -> Input {
        Input {
            path: path.into(),
            relative: relative.into(),
            walked: true,
        }
    }

    #[test]
    fn mirrors_the_tree_and_never_overwrites() {
        let inputs = [
            input("in/x/a.wkt", "x/a.wkt"),
            input("in/x/a.geojson", "x/a.geojson"),
            input("in/b.txt", "b.txt"),
            input("other/b.txt", "b.txt"),
            input("in/noext", "noext"),
            input("out/c.json", "c.json"),
        ];
        let got = plan(&inputs, Path::new("out"), "json");
        assert_eq!(got[0], Ok("out/x/a.wkt.json".into()));
        assert_eq!(got[1], Ok("out/x/a.geojson.json".into()));
        // Same relative path under two inputs: the second is refused, the first keeps its name
        // with the full input name kept, since both collided.
        assert_eq!(got[2], Ok("out/b.txt.json".into()));
        assert_eq!(
            got[3],
            Err(
                "not processed: its output out/b.txt.json would overwrite the output of in/b.txt"
                    .into()
            )
        );
        assert_eq!(got[4], Ok("out/noext.json".into()));
        // An input inside the output directory is never overwritten by its own output.
        assert_eq!(got[5], Ok("out/c.json.json".into()));
    }
}
