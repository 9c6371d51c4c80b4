//! The `wingbeat` command-line tool: JSON in, JSON out (CSV where a table is natural).
//! Run `wingbeat --help` and `wingbeat <command> --help` for the full story.

mod cli;

fn main() {
    match cli::run() {
        Ok(text) => {
            if text.ends_with('\n') {
                print!("{text}");
            } else if !text.is_empty() {
                println!("{text}");
            }
        }
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    }
}
