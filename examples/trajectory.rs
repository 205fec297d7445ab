//! Prints the first second of the six damping cases side by side, stepped at 60 fps with the
//! exact transition, and checks each against a single 1-second step.
//!
//! ```text
//! cargo run --example trajectory
//! ```

use sprung::{Spring, SpringError, SpringState};

fn main() -> Result<(), SpringError> {
    // Spring::new(mass, stiffness, damping): ω = 10 rad/s where there is a spring.
    let cases = [
        ("critical", Spring::new(1.0, 100.0, 20.0)?),
        ("under ζ=0.2", Spring::new(1.0, 100.0, 4.0)?),
        ("undamped", Spring::new(1.0, 100.0, 0.0)?),
        ("over ζ=3", Spring::new(1.0, 100.0, 60.0)?),
        ("unsprung", Spring::new(1.0, 0.0, 4.0)?),
        ("free", Spring::new(1.0, 0.0, 0.0)?),
    ];
    // Released 1 unit from the target at 0, moving toward it at 2 units/s.
    let start = SpringState::new(1.0_f64, -2.0);
    let frame = 1.0 / 60.0;

    print!("{:>6}", "t (s)");
    for (name, _) in &cases {
        print!(" {name:>12}");
    }
    println!();
    let mut states = [start; 6];
    let steps: Vec<_> = cases
        .iter()
        .map(|(_, spring)| spring.transition(frame))
        .collect();
    for i in 0..=60 {
        if i % 5 == 0 {
            print!("{:>6.3}", f64::from(i) * frame);
            for state in &states {
                print!(" {:>12.6}", state.position);
            }
            println!();
        }
        for (state, step) in states.iter_mut().zip(&steps) {
            *state = step.step(*state, 0.0);
        }
    }

    println!("\nafter 61 frames of 1/60 s vs one exact step of 61/60 s:");
    for ((name, spring), state) in cases.iter().zip(&states) {
        let once = spring.transition(61.0 * frame).step(start, 0.0);
        println!(
            "{name:>12}: {:+.15} vs {:+.15} (difference {:.1e})",
            state.position,
            once.position,
            (state.position - once.position).abs()
        );
    }
    Ok(())
}
