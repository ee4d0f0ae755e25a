package io.github.jdem846.cli;

import io.github.jdem846.render.RenderSettings;
import java.util.Locale;
import picocli.CommandLine.Command;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;

/** {@code --threads}, {@code --tile-size} and {@code --memory}, shared by the rendering subcommands. */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
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

    @Option(names = "--memory", paramLabel = "SIZE", converter = MemorySize.class,
            description = "Most memory the grids and pictures may take at once, e.g. 512m or 4g (default: half of"
                    + " Java's heap, -Xmx); a larger picture is rendered in tiles. The output does not depend on it.")
    Long memory;

    /** The settings these options describe. */
    RenderSettings settings() {
        return new RenderSettings(threads(), tileSize);
    }

    /** The worker threads: {@code --threads}, or all processors. */
    int threads() {
        return threads != null ? threads : RenderSettings.defaults().parallelism();
    }

    /** @return {@code --memory} in bytes, or 0 when not given (half the heap) */
    long memory() {
        return memory != null ? memory : 0;
    }

    /** {@code --memory}: bytes, or a number with k, m, g or t (binary: 1k = 1024 bytes), as for {@code -Xmx}. */
    static final class MemorySize implements ITypeConverter<Long> {
        @Override
        public Long convert(String text) {
            String t = text.trim().toLowerCase(Locale.ROOT);
            int shift = 0;
            if (!t.isEmpty()) {
                switch (t.charAt(t.length() - 1)) {
                    case 'k' -> shift = 10;
                    case 'm' -> shift = 20;
                    case 'g' -> shift = 30;
                    case 't' -> shift = 40;
                    default -> shift = -1;
                }
            }
            String digits = shift >= 0 ? t.substring(0, t.length() - 1) : t;
            String expected = "'" + text + "' is not a memory size: expected bytes or a whole number with k, m, g"
                    + " or t, e.g. 512m or 4g";
            long n;
            try {
                n = Long.parseLong(digits);
            } catch (NumberFormatException e) {
                throw new TypeConversionException(expected);
            }
            if (n <= 0) {
                throw new TypeConversionException(expected + ", above 0");
            }
            if (n > Long.MAX_VALUE >> Math.max(0, shift)) {
                throw new TypeConversionException(expected + ", below 8 EiB");
            }
            return n << Math.max(0, shift);
        }
    }
}
