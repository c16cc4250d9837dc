//! The friction stage's lamina traction against the integral as it stood before issue 31
//! (`physics::lubrication::traction::reference`), on every shipped spherical deck.

use super::*;
use crate::bearings::spherical_roller::deck;
use crate::bearings::spherical_roller::pipeline::{run, Request};
use crate::physics::lubrication::traction::{reference, HertzStrip};

/// Every shipped spherical deck (the decks of other systems do not load as one), solved.
fn shipped() -> Vec<(String, Bearing)> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("decks");
    let mut paths: Vec<_> = std::fs::read_dir(&dir)
        .expect("decks/")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    paths.sort();
    paths
        .into_iter()
        .filter_map(|p| {
            let text = std::fs::read_to_string(&p).ok()?;
            // Absent `type`: the default system, the spherical roller.
            let spherical = match crate::deck::deck_type(&text, "deck") {
                crate::deck::DeckType::Absent => true,
                crate::deck::DeckType::Named { id, .. } => {
                    id == crate::bearings::spherical_roller::SYSTEM_ID
                }
                crate::deck::DeckType::NotAString { .. } => false,
            };
            spherical.then(|| {
                let d = deck::load(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
                (p.display().to_string(), d.value)
            })
        })
        .collect()
}

/// Issue 31: the friction stage (the law's constants hoisted out of the lamina loop) gives
/// each loaded lamina's traction and heat of the old path bit for bit, for the EHD
/// and the lost-lubrication law, on every shipped spherical deck; the roller and bearing
/// totals follow (1e-12: a sum of the same terms). Same integral, same nodes, the same
/// constants: each lamina's numbers are equal bit for bit.
#[test]
fn friction_matches_the_reference_on_every_spherical_deck() {
    let decks = shipped();
    assert!(decks.len() >= 5, "spherical decks: {}", decks.len());
    for (name, b) in decks {
        let a = run(&b, &Request::default(), None).unwrap_or_else(|e| panic!("{name}: {e}"));
        let (st, fi) = (
            a.stresses.as_ref().expect("stresses"),
            a.films.as_ref().expect("films"),
        );
        let sp = internal_speeds(&b, &a.load, &a.contacts);
        let mut loaded = 0;
        for lost in [false, true] {
            let fr = friction(&b, &a.load, &a.contacts, st, fi, &sp, lost).expect("friction");
            let model = if lost {
                TractionModel::lost_lubrication(&b.lubricant)
            } else {
                TractionModel::ehd(&b.lubricant)
            };
            let mut total = 0.0;
            for (j, rc) in a.contacts.iter().enumerate() {
                for (i, pair) in rc.iter().enumerate() {
                    for (k, c) in pair.iter().enumerate() {
                        let got = fr.laminae[j][i][k];
                        if c.load_n <= 0.0 {
                            assert_eq!(got.heat_w, 0.0);
                            continue;
                        }
                        loaded += 1;
                        let want = reference::lamina_traction(
                            &model,
                            &HertzStrip {
                                load_n: c.load_n,
                                half_width_m: st.laminae[j][i][k].half_width_m,
                                width_m: c.width_m,
                            },
                            got.sliding_m_s,
                            fi.laminae[j][i][k].unwrap_or(0.0),
                        );
                        total += want.heat_w;
                        for (g, r) in [(got.traction_n, want.force_n), (got.heat_w, want.heat_w)] {
                            assert!(
                                g == r,
                                "{name} roller {j} lamina {i} raceway {k} lost {lost}: {g} vs {r}"
                            );
                        }
                    }
                }
            }
            let contact_w = fr.heat.inner_contacts_w + fr.heat.outer_contacts_w;
            assert!(
                (contact_w - total).abs() <= 1e-12 * total,
                "{name}: contact heat {contact_w} vs {total}"
            );
        }
        assert!(loaded > 0, "{name}: no loaded lamina");
    }
}
