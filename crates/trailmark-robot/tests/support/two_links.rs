//! The robot of the exact-tier and point-cloud tests: two links of spheres on a post, turning
//! about z and then y, and its one group. Included by path (`#[path = ...] mod two_links;`).

/// The URDF: a base sphere, an upper arm of two spheres, a forearm of two.
pub const URDF: &str = r#"
<robot name="two">
  <link name="base"><collision><origin xyz="0 0 0.1"/><geometry><sphere radius="0.1"/></geometry></collision></link>
  <link name="upper"><collision><origin xyz="0.2 0 0"/><geometry><sphere radius="0.06"/></geometry></collision>
                     <collision><origin xyz="0.4 0 0"/><geometry><sphere radius="0.05"/></geometry></collision></link>
  <link name="fore"><collision><origin xyz="0.15 0 0"/><geometry><sphere radius="0.05"/></geometry></collision>
                    <collision><origin xyz="0.3 0 0"/><geometry><sphere radius="0.04"/></geometry></collision></link>
  <joint name="yaw" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/><limit lower="-3" upper="3"/></joint>
  <joint name="pitch" type="revolute"><parent link="upper"/><child link="fore"/>
    <origin xyz="0.45 0 0"/><axis xyz="0 1 0"/><limit lower="-2.5" upper="2.5"/></joint>
</robot>"#;

/// The SRDF: the group `arm`, the chain from the base to the forearm.
pub const SRDF: &str =
    r#"<robot name="two"><group name="arm"><chain base_link="base" tip_link="fore"/></group></robot>"#;
