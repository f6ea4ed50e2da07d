//! Saving and loading a polygon roadmap.

use serde::{Deserialize, Serialize};
use trailmark_core::world::PolygonWorld;
use trailmark_space::sampler::Halton;

use super::{Drawer, PlanarSpace, PolygonPrm, PrmError, PrmOptions};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// A saved roadmap: the world, the space, the settings, the nodes, every edge tried and where
/// the sample stream stands.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct PrmDocument<S> {
    world: PolygonWorld,
    space: S,
    options: PrmOptions,
    /// `[x, y]` or `[x, y, heading]`.
    nodes: Vec<Vec<f64>>,
    /// `[from, to, free (1) or blocked (0)]`.
    edges: Vec<[u32; 3]>,
    /// How far the ChaCha8 stream has gone (in 32-bit words), and the Halton index.
    stream: StreamDocument,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct StreamDocument {
    /// The word position, as a decimal string (it may exceed 2^64).
    word_position: String,
    halton_index: u64,
    attempts: u64,
}

impl<S: PlanarSpace + Serialize> Serialize for PolygonPrm<S> {
    /// Saves as `{"world", "space", "options", "nodes", "edges", "stream"}`.
    fn serialize<Ser: serde::Serializer>(&self, serializer: Ser) -> Result<Ser::Ok, Ser::Error> {
        PrmDocument {
            world: self.checker.world().clone(),
            space: self.space.clone(),
            options: self.options,
            nodes: (0..self.node_count() as u32)
                .map(|u| self.space.coordinates(self.roadmap.state(u)))
                .collect(),
            edges: self
                .roadmap
                .tried
                .iter()
                .map(|c| [c.ends[0], c.ends[1], u32::from(c.cost.is_finite())])
                .collect(),
            stream: StreamDocument {
                // A stream not drawn from yet is at its start.
                word_position: self.roadmap.rng.as_ref().map_or(0, |rng| rng.get_word_pos()).to_string(),
                halton_index: match &self.roadmap.sampler {
                    Drawer::Halton(halton) => halton.drawn(),
                    _ => 0,
                },
                attempts: self.attempts,
            },
        }
        .serialize(serializer)
    }
}

impl<'de, S: PlanarSpace + Deserialize<'de>> Deserialize<'de> for PolygonPrm<S> {
    /// Loads a saved roadmap, re-checking every node and every edge's free or blocked state in
    /// the saved world; a mismatch is an error, not a silent repair.
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let document = PrmDocument::<S>::deserialize(deserializer)?;
        PolygonPrm::from_document(document).map_err(serde::de::Error::custom)
    }
}

impl<S: PlanarSpace> PolygonPrm<S> {
    fn from_document(d: PrmDocument<S>) -> Result<Self, PrmError> {
        let mut prm = PolygonPrm::with_space(d.world, d.space, d.options)?;
        for (index, coordinates) in d.nodes.iter().enumerate() {
            let state =
                prm.space.state_from_coordinates(coordinates).ok_or(PrmError::InvalidNode { index })?;
            if !prm.is_free(&state) || prm.roadmap.find(&prm.space, &state).is_some() {
                return Err(PrmError::InvalidNode { index });
            }
            prm.roadmap.push(&prm.space, state);
        }
        let n = prm.node_count() as u32;
        for (index, &[from, to, free]) in d.edges.iter().enumerate() {
            if from >= n || to >= n || from == to || free > 1 {
                return Err(PrmError::InvalidEdge { index });
            }
            let cost = prm.local_path(&prm.checker, from, to);
            prm.roadmap.record(from, to, cost);
            if cost.is_some() != (free == 1) {
                return Err(PrmError::InvalidEdge { index });
            }
        }
        let word_position: u128 = d.stream.word_position.parse().map_err(|_| PrmError::InvalidStream)?;
        let mut rng = ChaCha8Rng::seed_from_u64(prm.options.sampler.seed());
        rng.set_word_pos(word_position);
        prm.roadmap.rng = Some(rng);
        if let Drawer::Halton(halton) = &mut prm.roadmap.sampler {
            *halton = Halton::after(d.stream.halton_index);
        }
        prm.attempts = d.stream.attempts;
        prm.roadmap.checks = 0;
        Ok(prm)
    }
}
