//! `approx` comparisons for the public value types.

use approx::{AbsDiffEq, RelativeEq, UlpsEq};

use crate::{Scalar, Spring, SpringState, Transition};

/// Compares `(mass, stiffness, damping)`.
impl<T: Scalar> AbsDiffEq for Spring<T> {
    type Epsilon = T;

    fn default_epsilon() -> T {
        T::default_epsilon()
    }

    fn abs_diff_eq(&self, other: &Self, epsilon: T) -> bool {
        parameters(self).abs_diff_eq(&parameters(other), epsilon)
    }
}

impl<T: Scalar> RelativeEq for Spring<T> {
    fn default_max_relative() -> T {
        T::default_max_relative()
    }

    fn relative_eq(&self, other: &Self, epsilon: T, max_relative: T) -> bool {
        parameters(self).relative_eq(&parameters(other), epsilon, max_relative)
    }
}

impl<T: Scalar> UlpsEq for Spring<T> {
    fn default_max_ulps() -> u32 {
        T::default_max_ulps()
    }

    fn ulps_eq(&self, other: &Self, epsilon: T, max_ulps: u32) -> bool {
        parameters(self).ulps_eq(&parameters(other), epsilon, max_ulps)
    }
}

fn parameters<T: Scalar>(spring: &Spring<T>) -> [T; 3] {
    [spring.mass(), spring.stiffness(), spring.damping()]
}

/// Compares `dt` and the matrix entries.
impl<T: Scalar> AbsDiffEq for Transition<T> {
    type Epsilon = T;

    fn default_epsilon() -> T {
        T::default_epsilon()
    }

    fn abs_diff_eq(&self, other: &Self, epsilon: T) -> bool {
        entries(self).abs_diff_eq(&entries(other), epsilon)
    }
}

impl<T: Scalar> RelativeEq for Transition<T> {
    fn default_max_relative() -> T {
        T::default_max_relative()
    }

    fn relative_eq(&self, other: &Self, epsilon: T, max_relative: T) -> bool {
        entries(self).relative_eq(&entries(other), epsilon, max_relative)
    }
}

impl<T: Scalar> UlpsEq for Transition<T> {
    fn default_max_ulps() -> u32 {
        T::default_max_ulps()
    }

    fn ulps_eq(&self, other: &Self, epsilon: T, max_ulps: u32) -> bool {
        entries(self).ulps_eq(&entries(other), epsilon, max_ulps)
    }
}

fn entries<T: Scalar>(transition: &Transition<T>) -> [T; 5] {
    let [[a, b], [c, d]] = transition.matrix();
    [transition.dt(), a, b, c, d]
}

/// Compares position and velocity with the value type's own comparison.
impl<V: AbsDiffEq> AbsDiffEq for SpringState<V>
where
    V::Epsilon: Copy,
{
    type Epsilon = V::Epsilon;

    fn default_epsilon() -> V::Epsilon {
        V::default_epsilon()
    }

    fn abs_diff_eq(&self, other: &Self, epsilon: V::Epsilon) -> bool {
        self.position.abs_diff_eq(&other.position, epsilon)
            && self.velocity.abs_diff_eq(&other.velocity, epsilon)
    }
}

impl<V: RelativeEq> RelativeEq for SpringState<V>
where
    V::Epsilon: Copy,
{
    fn default_max_relative() -> V::Epsilon {
        V::default_max_relative()
    }

    fn relative_eq(&self, other: &Self, epsilon: V::Epsilon, max_relative: V::Epsilon) -> bool {
        self.position
            .relative_eq(&other.position, epsilon, max_relative)
            && self
                .velocity
                .relative_eq(&other.velocity, epsilon, max_relative)
    }
}

impl<V: UlpsEq> UlpsEq for SpringState<V>
where
    V::Epsilon: Copy,
{
    fn default_max_ulps() -> u32 {
        V::default_max_ulps()
    }

    fn ulps_eq(&self, other: &Self, epsilon: V::Epsilon, max_ulps: u32) -> bool {
        self.position.ulps_eq(&other.position, epsilon, max_ulps)
            && self.velocity.ulps_eq(&other.velocity, epsilon, max_ulps)
    }
}

#[cfg(test)]
mod tests {
    use approx::{assert_relative_eq, assert_ulps_eq};

    use crate::{Spring, SpringState};

    #[test]
    fn springs_transitions_and_states_compare_approximately() {
        let a = Spring::<f64>::new(1.0, 100.0, 10.0).unwrap();
        let b = Spring::<f64>::new(1.0, 100.0 + 1e-13, 10.0).unwrap();
        assert_relative_eq!(a, b, max_relative = 1e-14);
        assert!(approx::relative_ne!(
            a,
            Spring::new(1.0, 101.0, 10.0).unwrap()
        ));
        assert_ulps_eq!(a.transition(0.1), b.transition(0.1), max_ulps = 64);
        assert!(approx::abs_diff_ne!(a.transition(0.1), a.transition(0.2)));
        let s = SpringState::new(1.0_f64, 2.0);
        assert_relative_eq!(s, SpringState::new(1.0 + 1e-15, 2.0), max_relative = 1e-14);
        assert!(approx::relative_ne!(s, SpringState::new(1.0, 2.1)));
    }
}
