//! `--completions SHELL` and `--man`: the completion script and the man page, generated from
//! the same clap definition as the flags themselves.

use crate::args::Flags;
use clap::CommandFactory;
use std::io::{self, Write};

/// Writes what `--completions` or `--man` asks for to `out`; `Ok(false)` when neither was given
/// (the run goes on to read its inputs).
pub fn generate(flags: &Flags, out: &mut impl Write) -> io::Result<bool> {
    let mut cmd = Flags::command();
    // Rendered to memory first: clap_complete panics on a write error (a closed pipe).
    let mut text = Vec::new();
    if let Some(shell) = flags.completions {
        clap_complete::generate(shell, &mut cmd, "minitri", &mut text);
    } else if flags.man {
        man(cmd, &mut text)?;
    } else {
        return Ok(false);
    }
    out.write_all(&text)?;
    out.flush()?;
    Ok(true)
}

/// The man page: clap_mangen's sections, with the examples of `--help` as EXAMPLES (unfilled,
/// so that their columns stay) instead of its generic EXTRA section.
fn man(cmd: clap::Command, out: &mut Vec<u8>) -> io::Result<()> {
    let extra = cmd
        .get_after_long_help()
        .map(|text| text.to_string())
        .unwrap_or_default();
    let man = clap_mangen::Man::new(cmd);
    man.render_title(out)?;
    man.render_name_section(out)?;
    man.render_synopsis_section(out)?;
    man.render_description_section(out)?;
    man.render_options_section(out)?;
    let body = extra.strip_prefix("Examples:\n").unwrap_or(&extra);
    writeln!(out, ".SH EXAMPLES\n.nf")?;
    for line in body.lines() {
        let line = line
            .replace('\\', "\\e")
            .replace('-', "\\-")
            .replace('\'', "\\(aq");
        if line.starts_with('.') {
            writeln!(out, "\\&{line}")?;
        } else {
            writeln!(out, "{line}")?;
        }
    }
    writeln!(out, ".fi")?;
    man.render_version_section(out)
}
