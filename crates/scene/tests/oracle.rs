//! The runner against the exact oracle (`polydist-oracle`, rational brute force) on random moving
//! convex pairs: per-frame distances within the convex crate's error budget, and every
//! `first_contact` answer checked at the rounded posed coordinates: the exact contact status at
//! `t_hit`, disjointness sampled over `[start, t_safe]`, and the certified clearance never above an
//! exact distance sampled over the span.

use glam::DVec2;
use polydist_oracle::{
    Contact, contact_status_convex, convex_distance, sqrt_nearest, ulps_error_sqrt,
};
use polydist_scene::{Body, ContactOutcome, Origin, RunOptions, Status, load_str, run};
use proptest::prelude::*;

/// The body as the runner poses it: its internal vertices moved by `Pose::apply`.
fn posed(b: &Body, t: f64) -> Vec<DVec2> {
    let pose = b.motion.pose_at(t);
    b.shape.vertices().iter().map(|&v| pose.apply(v)).collect()
}

fn shape(kind: u8, n: u64, r: f64, seed: u64) -> String {
    if kind == 0 {
        format!("generator = {{ type = \"regular\", n = {n}, radius = {r} }}")
    } else {
        format!("generator = {{ type = \"random_convex\", n = {n}, radius = {r}, seed = {seed} }}")
    }
}

fn scene_text(
    sa: String,
    sb: String,
    (xa, ya, aa): (f64, f64, f64),
    (vx, vy, wa): (f64, f64, f64),
    (xb, yb, ab): (f64, f64, f64),
    wb: f64,
    end: f64,
) -> String {
    format!(
        r#"
        time = {{ end = {end}, step = {step} }}
        [[body]]
        id = "a"
        {sa}
        pose = {{ x = {xa}, y = {ya}, angle = {aa} }}
        motion = {{ type = "linear", velocity = [{vx}, {vy}], angular = {wa} }}
        [[body]]
        id = "b"
        {sb}
        pose = {{ x = {xb}, y = {yb}, angle = {ab} }}
        motion = {{ type = "linear", angular = {wb} }}
        [[query]]
        pairs = [["a", "b"]]
        effects = ["distance", "first_contact"]
        "#,
        step = end / 8.0
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn runner_agrees_with_the_exact_oracle(
        ka in 0u8..2, na in 3u64..10, ra in 0.3f64..1.5, seed_a in 0u64..(1 << 62),
        kb in 0u8..2, nb in 3u64..10, rb in 0.3f64..1.5, seed_b in 0u64..(1 << 62),
        start_a in (-6.0f64..-2.0, -2.0f64..2.0, -3.0f64..3.0),
        vel_a in (1.0f64..4.0, -1.0f64..1.0, -2.0f64..2.0),
        pose_b in (1.0f64..5.0, -2.0f64..2.0, -3.0f64..3.0),
        wb in -1.0f64..1.0,
        end in 1.0f64..6.0,
    ) {
        let text = scene_text(
            shape(ka, na, ra, seed_a),
            shape(kb, nb, rb, seed_b),
            start_a, vel_a, pose_b, wb, end,
        );
        let scene = load_str(&text, &Origin::text("oracle.toml")).unwrap();
        let report = run(&scene, &RunOptions::default());
        let (a, b) = (&scene.bodies[0], &scene.bodies[1]);
        let pair = &report.pairs[0];
        for f in &pair.frames {
            prop_assume!(f.status != Some(Status::Invalid));
            let exact = convex_distance(&posed(a, f.t), &posed(b, f.t));
            let d = f.distance.unwrap();
            prop_assert!(ulps_error_sqrt(d, &exact.sq) <= 3.0, "t = {}: {} vs {}", f.t, d, sqrt_nearest(&exact.sq));
        }
        let c = pair.first_contact.clone().unwrap();
        let meets = |t: f64| contact_status_convex(&posed(a, t), &posed(b, t)) != Contact::Disjoint;
        let samples = |lo: f64, hi: f64| (0..=40).map(move |k| lo + (hi - lo) * f64::from(k) / 40.0);
        match c.outcome {
            ContactOutcome::ContactAtStart => prop_assert!(meets(0.0)),
            ContactOutcome::Contact => {
                let (safe, hit) = (c.t_safe.unwrap(), c.t_hit.unwrap());
                prop_assert!(safe < hit && hit - safe <= c.tolerance);
                prop_assert!(meets(hit), "no contact at t_hit = {}", hit);
                for t in samples(0.0, safe) {
                    prop_assert!(!meets(t), "contact at {} before t_safe = {}", t, safe);
                }
            }
            ContactOutcome::Apart => {
                let lb = c.clearance_lower_bound.unwrap();
                prop_assert!(lb > 0.0);
                for t in samples(0.0, end) {
                    let exact = sqrt_nearest(&convex_distance(&posed(a, t), &posed(b, t)).sq);
                    prop_assert!(lb <= exact, "t = {}: bound {} above the exact distance {}", t, lb, exact);
                }
            }
            ContactOutcome::Undecided => {
                // Allowed (a grazing contact), but what it certifies must hold.
                for t in samples(0.0, c.t_safe.unwrap_or(0.0)) {
                    prop_assert!(!meets(t));
                }
            }
            ContactOutcome::Invalid => {}
        }
    }
}
