//! Fuzzing the parsers and constructors with proptest: arbitrary and mutated input never
//! panics, accepted input is consistent, and writing then reading a map gives it back.

use proptest::prelude::*;
use trailmark_core::grid::{Cell, Grid};
use trailmark_core::movingai::{parse_map, parse_scenarios, write_map};

const MAP: &str = "type octile\nheight 4\nwidth 5\nmap\n..@..\n.TT..\nS..W.\n....G\n";
const SCEN: &str =
    "version 1\n0\tmaps/x.map\t5\t4\t0\t0\t4\t3\t5.24264069\n1 maps/x.map 5 4 1 0 0 3 3.41421356\n";

/// `text` with random edits: characters replaced, inserted or deleted.
fn mutated(text: &'static str) -> impl Strategy<Value = String> {
    let edit = (any::<prop::sample::Index>(), 0u8..3, prop::char::range(' ', '~'));
    prop::collection::vec(edit, 1..6).prop_map(move |edits| {
        let mut chars: Vec<char> = text.chars().collect();
        for (at, kind, c) in edits {
            let i = at.index(chars.len() + 1);
            match kind {
                0 if i < chars.len() => chars[i] = c,
                1 => chars.insert(i, c),
                _ if i < chars.len() => {
                    chars.remove(i);
                }
                _ => {}
            }
        }
        chars.into_iter().collect()
    })
}

fn grid() -> impl Strategy<Value = Grid> {
    (1usize..20, 1usize..20).prop_flat_map(|(w, h)| {
        prop::collection::vec(any::<bool>(), w * h).prop_map(move |blocked| {
            let costs = blocked.iter().map(|&b| if b { f64::INFINITY } else { 1.0 }).collect();
            Grid::from_costs(w, h, costs).unwrap()
        })
    })
}

fn valid_cost(c: f64) -> bool {
    c == f64::INFINITY || (c.is_finite() && c > 0.0)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(5000))]

    #[test]
    fn arbitrary_text_never_panics(text in ".{0,200}") {
        let _ = parse_map(&text);
        let _ = parse_scenarios(&text);
        let rows: Vec<&str> = text.lines().collect();
        let _ = Grid::from_rows(&rows);
    }

    #[test]
    fn mutated_maps_parse_consistently_or_fail_with_a_line(text in mutated(MAP)) {
        match parse_map(&text) {
            Ok(grid) => {
                prop_assert_eq!(grid.len(), grid.width() as usize * grid.height() as usize);
                prop_assert_eq!(parse_map(&write_map(&grid)).unwrap(), grid);
            }
            Err(e) => {
                let lines = text.split('\n').count();
                prop_assert!(e.line >= 1 && e.line <= lines, "line {} of {}", e.line, lines);
            }
        }
    }

    #[test]
    fn mutated_scenarios_parse_consistently_or_fail_with_a_line(text in mutated(SCEN)) {
        match parse_scenarios(&text) {
            Ok(list) => {
                for s in list {
                    prop_assert!(s.start.x < s.map_width && s.goal.y < s.map_height);
                    prop_assert!(s.optimal_length.is_finite() && s.optimal_length >= 0.0);
                }
            }
            Err(e) => prop_assert!(e.line >= 1 && e.line <= text.split('\n').count()),
        }
    }

    #[test]
    fn written_maps_read_back_identical(grid in grid()) {
        let text = write_map(&grid);
        prop_assert_eq!(parse_map(&text).unwrap(), grid.clone());
        // CRLF line ends read the same.
        prop_assert_eq!(parse_map(&text.replace('\n', "\r\n")).unwrap(), grid);
    }

    #[test]
    fn cost_constructors_reject_exactly_the_invalid_costs(costs in prop::collection::vec(
        prop_oneof![Just(f64::NAN), Just(f64::NEG_INFINITY), Just(f64::INFINITY), Just(0.0), Just(-0.0), -5.0f64..5.0],
        1..30,
    )) {
        let n = costs.len();
        let built = Grid::from_costs(n, 1, costs.clone());
        prop_assert_eq!(built.is_ok(), costs.iter().all(|&c| valid_cost(c)));
        let mut grid = Grid::new(n, 1).unwrap();
        for (x, &c) in costs.iter().enumerate() {
            let before = grid.cost(Cell::new(x as u32, 0));
            let ok = grid.set_cost(Cell::new(x as u32, 0), c).is_ok();
            prop_assert_eq!(ok, valid_cost(c));
            if !ok {
                prop_assert_eq!(grid.cost(Cell::new(x as u32, 0)), before, "a rejected cost changes nothing");
            }
        }
    }
}
