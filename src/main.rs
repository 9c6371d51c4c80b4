//! The `wingbeat` command-line tool: JSON in, JSON out (CSV where a table is natural).
//! Run `wingbeat --help` and `wingbeat <command> --help` for the full story.

mod cli;

use std::io::Write;

fn main() {
    match cli::run() {
        Ok(text) => {
            let mut out = std::io::stdout().lock();
            let r = if text.is_empty() || text.ends_with('\n') {
                out.write_all(text.as_bytes())
            } else {
                writeln!(out, "{text}")
            };
            // A closed pipe (e.g. `| head`) is not an error worth a panic or a message.
            match r.and_then(|_| out.flush()) {
                Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
                    eprintln!("error: writing output: {e}");
                    std::process::exit(2);
                }
                _ => {}
            }
        }
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    }
}
