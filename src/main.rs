fn main() -> color_eyre::Result<()> {
    color_eyre::install()?;
    // Placeholder until the lead's CLI lands: `rollbench [DECK]` opens the workbench.
    let path = std::env::args_os().nth(1).map(std::path::PathBuf::from);
    let text = match &path {
        Some(p) => std::fs::read_to_string(p)?,
        None => rollbench::deck::DEFAULT_DECK.to_string(),
    };
    rollbench::tui::run_workbench(&text, path)
}
