fn main() {
    println!("rollbench: under construction");
}
