//! Runs the accuracy-vs-cost study: `cargo run --release -p sprung_study`.

fn main() -> Result<(), Box<dyn std::error::Error>> {
    sprung_study::run()
}
