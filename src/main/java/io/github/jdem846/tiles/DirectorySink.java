package io.github.jdem846.tiles;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

/**
 * Tiles as {@code DIR/z/x/y.png}, written into a hidden staging directory beside {@code DIR} and renamed to it at
 * the end. An existing {@code DIR} must be empty (it is then replaced); a run stopped without a chance to clean up
 * (the process killed) leaves the staging directory, {@code .DIR.jdem846-partial-…}, which can be deleted.
 */
final class DirectorySink implements TileSink {

    private final Path target;
    private final Path staging;
    private boolean committed;

    DirectorySink(Path target) throws IOException {
        this.target = target;
        checkTarget(target);
        this.staging = StagingDirectory.siblingOf(target);
        Files.createDirectory(staging);
    }

    /**
     * Fails before any work when {@code target} cannot become the tile directory.
     *
     * @throws IOException naming the directory and what is wrong
     */
    static void checkTarget(Path target) throws IOException {
        Path parent = StagingDirectory.parentOf(target);
        if (!Files.isDirectory(parent)) {
            throw new IOException("cannot write tiles to " + target + ": directory " + parent + " does not exist");
        }
        if (!Files.isWritable(parent)) {
            throw new IOException("cannot write tiles to " + target + ": directory " + parent + " is not writable");
        }
        if (Files.exists(target)) {
            if (!Files.isDirectory(target)) {
                throw new IOException("cannot write tiles to " + target + ": it is a file, not a directory (name a "
                        + "new or empty directory, or a .pmtiles file)");
            }
            try (Stream<Path> entries = Files.list(target)) {
                if (entries.findAny().isPresent()) {
                    throw new IOException("cannot write tiles to " + target + ": the directory is not empty (remove "
                            + "it or name a new one)");
                }
            }
        }
    }

    @Override
    public void write(WebMercatorTile tile, byte[] png) throws IOException {
        Path dir = staging.resolve(Integer.toString(tile.z())).resolve(Integer.toString(tile.x()));
        Files.createDirectories(dir);
        Files.write(dir.resolve(tile.y() + ".png"), png);
    }

    @Override
    public void commit(TileSetInfo info) throws IOException {
        if (Files.isDirectory(target)) {
            checkTarget(target);
            Files.delete(target); // empty, as checked
        }
        StagingDirectory.move(staging, target, false);
        committed = true;
    }

    @Override
    public void close() throws IOException {
        if (!committed) {
            StagingDirectory.deleteTree(staging);
        }
    }
}
