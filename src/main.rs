fn main() -> color_eyre::Result<()> {
    color_eyre::install()?;
    rollbench::tui::run_workbench(rollbench::deck::DEFAULT_DECK, None)
}
