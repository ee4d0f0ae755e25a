package io.github.jdem846.cli;

import io.github.jdem846.render.RenderSettings;
import picocli.CommandLine.Option;

/** {@code --threads} and {@code --tile-size}, shared by the rendering subcommands. */
public final class ExecutionOptions {

    @Option(names = "--threads", paramLabel = "N", converter = Converters.Threads.class,
            description = "Worker threads, also for compressing the output: 1 to " + RenderSettings.MAX_PARALLELISM
                    + " (default: all ${sys:jdem846.cpus:-available} processors).")
    Integer threads;

    @Option(names = "--tile-size", paramLabel = "CELLS", converter = Converters.TileSize.class,
            description = "Tile edge in cells, " + RenderSettings.MIN_TILE_SIZE + " to " + RenderSettings.MAX_TILE_SIZE
                    + " (default: ${DEFAULT-VALUE}); the output does not depend on it.",
            defaultValue = "" + RenderSettings.DEFAULT_TILE_SIZE)
    int tileSize;

    /** The settings these options describe. */
    RenderSettings settings() {
        return new RenderSettings(threads(), tileSize);
    }

    /** The worker threads: {@code --threads}, or all processors. */
    int threads() {
        return threads != null ? threads : RenderSettings.defaults().parallelism();
    }
}
