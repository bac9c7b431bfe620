// placeholder so the target has a source; remove once the folder has real sources
