use rollbench::deck::Deck;
use rollbench::solve::pipeline::{run, Request};
fn main() {
    let mut b = Deck::load("decks/industrial.toml").unwrap().bearing;
    b.solver.laminae = 21;
    println!("{:?}", run(&b, &Request::default(), None).err());
}
