//! JSON `rings` (issue 29 item 1): every system with rings says the ring's tilt and moment.
//! The tapered system adds the x components where non-zero; the self-aligning systems
//! (spherical outer raceway) carry no moment and say the tilt is free.

use assert_cmd::Command;

fn json(deck: &str, sets: &[&str]) -> serde_json::Value {
    let d = format!("{}/decks/{deck}", env!("CARGO_MANIFEST_DIR"));
    let mut args = vec!["run", d.as_str(), "--format", "json"];
    for s in sets {
        args.extend(["--set", s]);
    }
    let out = match Command::cargo_bin("rollbench").map(|mut c| c.args(&args).output()) {
        Ok(Ok(o)) => o,
        Ok(Err(e)) => panic!("{e}"),
        Err(e) => panic!("{e}"),
    };
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{e}"))
}

/// A cone held at θx = 0.01° (trb_afapl, US deck: the key in degrees) writes
/// `tilt_x_rad` = 0.01° in radians (1e-12) and a non-zero `moment_x_nm` equal to the
/// `reaction_moment_nm` x entry; without it neither key is written (M_x is then
/// round-off of the x–z symmetry).
#[test]
fn tapered_writes_the_x_tilt_where_non_zero() {
    let plain = json("trb_afapl.toml", &[]);
    assert!(
        plain["rings"].get("tilt_x_rad").is_none(),
        "{}",
        plain["rings"]
    );
    assert!(plain["rings"].get("moment_x_nm").is_none());
    let v = json("trb_afapl.toml", &["operating.misalignment_x=0.01"]);
    let r = &v["rings"];
    let t = r["tilt_x_rad"].as_f64().unwrap_or(f64::NAN);
    assert!((t - 0.01f64.to_radians()).abs() < 1e-12 * t.abs(), "{r}");
    let m = r["moment_x_nm"].as_f64().unwrap_or(f64::NAN);
    assert!(
        m != 0.0 && m == r["reaction_moment_nm"][0].as_f64().unwrap_or(f64::NAN),
        "{r}"
    );
}

/// The single- and double-row spherical rollers: `moment_nm` 0 and `tilt_free` true.
#[test]
fn self_aligning_rings_carry_no_moment() {
    for deck in ["radial_si.toml", "srb_22308.toml"] {
        let v = json(deck, &[]);
        assert_eq!(v["rings"]["moment_nm"], 0.0, "{deck}: {}", v["rings"]);
        assert_eq!(v["rings"]["tilt_free"], true, "{deck}");
    }
}
