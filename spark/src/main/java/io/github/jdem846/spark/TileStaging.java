package io.github.jdem846.spark;

import io.github.jdem846.tiles.EncodedTile;
import io.github.jdem846.tiles.TileFormat;
import io.github.jdem846.tiles.TilePlan;
import io.github.jdem846.tiles.TileSink;
import io.github.jdem846.tiles.WebMercatorTile;
import java.io.IOException;
import java.io.InputStream;
import java.io.Serializable;
import java.net.URI;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.UUID;
import org.apache.hadoop.conf.Configuration;
import org.apache.hadoop.fs.FSDataOutputStream;
import org.apache.hadoop.fs.FileStatus;
import org.apache.hadoop.fs.FileSystem;
import org.apache.hadoop.fs.Path;
import org.apache.hadoop.io.IOUtils;

/**
 * The output of a Spark tile job on any Hadoop file system: executors write each tile as {@code z/x/y.png} into a
 * hidden staging directory beside the output ({@code .NAME.jdem846-partial-…}), each through a hidden temporary file
 * renamed into place, so a task retried by Spark writes the same bytes again and no half-written tile is ever seen.
 * When every task has finished, the driver renames the staging directory to the output directory, or packs its tiles
 * into a PMTiles archive with the library's writer; a failed job deletes it.
 */
final class TileStaging implements Serializable {

    private static final long serialVersionUID = 1L;

    private final String target;
    private final String staging;
    private final TileFormat format;

    private TileStaging(String target, String staging, TileFormat format) {
        this.target = target;
        this.staging = staging;
        this.format = format;
    }

    /**
     * Checks that the output can be written and creates the staging directory.
     *
     * @param output a directory that does not exist or is empty, or a name ending in {@code .pmtiles}
     * @throws IOException naming the output and what is wrong with it
     */
    static TileStaging create(String output, Configuration conf) throws IOException {
        Path target = qualified(output, conf);
        TileFormat format = TileFormat.of(java.nio.file.Path.of(target.getName()));
        FileSystem fs = fileSystem(target, conf);
        Path parent = target.getParent();
        if (parent == null || !fs.isDirectory(parent)) {
            throw new IOException("cannot write tiles to " + output + ": directory " + parent + " does not exist");
        }
        if (fs.exists(target)) {
            FileStatus s = fs.getFileStatus(target);
            if (format == TileFormat.PMTILES && s.isDirectory()) {
                throw new IOException("cannot write " + output + ": it is a directory");
            }
            if (format == TileFormat.DIRECTORY && !s.isDirectory()) {
                throw new IOException("cannot write tiles to " + output + ": it is a file, not a directory (name a "
                        + "new or empty directory, or a .pmtiles file)");
            }
            if (format == TileFormat.DIRECTORY && fs.listStatus(target).length > 0) {
                throw new IOException("cannot write tiles to " + output + ": the directory is not empty (remove it "
                        + "or name a new one)");
            }
        }
        Path staging = new Path(parent, "." + target.getName() + ".jdem846-partial-" + UUID.randomUUID());
        if (!fs.mkdirs(staging)) {
            throw new IOException("cannot write tiles to " + output + ": cannot create " + staging);
        }
        return new TileStaging(target.toString(), staging.toString(), format);
    }

    /** @return the output's format */
    TileFormat format() {
        return format;
    }

    /** @return the output as a qualified URI */
    String target() {
        return target;
    }

    /**
     * Writes one tile: to a temporary name unique to this attempt, then renamed over any earlier attempt's copy.
     * Local files are written with {@code java.nio} (Hadoop's local file system sets permissions file by file, which
     * costs more than the tile itself), others through Hadoop.
     */
    void write(EncodedTile tile, Configuration conf, String attempt) throws IOException {
        WebMercatorTile t = tile.tile();
        String rel = t.z() + "/" + t.x() + "/";
        String name = t.y() + ".png";
        String temp = "." + name + "." + attempt;
        Path dir = new Path(staging + "/" + rel);
        if ("file".equals(dir.toUri().getScheme())) {
            java.nio.file.Path local = java.nio.file.Path.of(dir.toUri());
            java.nio.file.Files.createDirectories(local);
            java.nio.file.Path written = java.nio.file.Files.write(local.resolve(temp), tile.png());
            java.nio.file.Files.move(written, local.resolve(name), StandardCopyOption.ATOMIC_MOVE,
                    StandardCopyOption.REPLACE_EXISTING);
            return;
        }
        Path done = new Path(dir, name);
        Path part = new Path(dir, temp);
        FileSystem fs = fileSystem(done, conf);
        try (FSDataOutputStream out = fs.create(part, true)) {
            out.write(tile.png());
        }
        if (!fs.rename(part, done)) {
            // an earlier attempt's copy is in the way (Hadoop's rename does not replace): the bytes are the same
            fs.delete(done, false);
            if (!fs.rename(part, done)) {
                throw new IOException("cannot rename " + part + " to " + done);
            }
        }
    }

    /**
     * Moves the finished tiles into place: the staging directory renamed to the output directory, or its tiles
     * packed into the PMTiles archive (written locally first when the output is on another file system).
     */
    void commit(TilePlan plan, Configuration conf) throws IOException {
        Path out = new Path(target);
        FileSystem fs = fileSystem(out, conf);
        Path stage = new Path(staging);
        deleteTemporaries(fs, stage);
        if (format == TileFormat.DIRECTORY) {
            if (fs.exists(out)) {
                fs.delete(out, false); // empty, as checked
            }
            if (!fs.rename(stage, out)) {
                throw new IOException("cannot rename " + stage + " to " + out);
            }
            return;
        }
        boolean local = "file".equals(out.toUri().getScheme());
        java.nio.file.Path archive = local ? java.nio.file.Path.of(out.toUri())
                : java.nio.file.Files.createTempDirectory("jdem846-spark").resolve(out.getName());
        try (TileSink sink = TileSink.open(archive)) {
            for (Path p : filesUnder(fs, stage)) {
                WebMercatorTile tile = tileOf(stage, p);
                byte[] png = new byte[(int) fs.getFileStatus(p).getLen()];
                try (InputStream in = fs.open(p)) {
                    IOUtils.readFully(in, png, 0, png.length);
                }
                sink.write(tile, png);
            }
            sink.commit(plan.tileSetInfo());
        }
        if (!local) {
            Path hidden = new Path(out.getParent(), "." + out.getName() + ".jdem846-upload-" + UUID.randomUUID());
            try {
                fs.copyFromLocalFile(true, false, new Path(archive.toUri()), hidden);
                if (fs.exists(out)) {
                    fs.delete(out, false);
                }
                if (!fs.rename(hidden, out)) {
                    throw new IOException("cannot rename " + hidden + " to " + out);
                }
            } finally {
                fs.delete(hidden, false);
                java.nio.file.Files.deleteIfExists(archive);
                java.nio.file.Files.deleteIfExists(archive.getParent());
            }
        }
        fs.delete(stage, true);
    }

    /** Deletes the staging directory and everything in it. */
    void abort(Configuration conf) throws IOException {
        Path stage = new Path(staging);
        fileSystem(stage, conf).delete(stage, true);
    }

    private static WebMercatorTile tileOf(Path stage, Path file) throws IOException {
        String rel = stage.toUri().relativize(file.toUri()).getPath();
        String[] parts = rel.split("/");
        if (parts.length != 3 || !parts[2].endsWith(".png")) {
            throw new IOException("unexpected file " + file + " among the staged tiles");
        }
        return new WebMercatorTile(Integer.parseInt(parts[0]), Integer.parseInt(parts[1]),
                Integer.parseInt(parts[2].substring(0, parts[2].length() - 4)));
    }

    /** Temporaries of attempts that did not get to rename them (an executor lost mid-write). */
    private static void deleteTemporaries(FileSystem fs, Path stage) throws IOException {
        for (Path p : filesUnder(fs, stage)) {
            if (p.getName().startsWith(".")) {
                fs.delete(p, false);
            }
        }
    }

    /** Every file under {@code root}, depth first, in name order. */
    private static List<Path> filesUnder(FileSystem fs, Path root) throws IOException {
        List<Path> out = new ArrayList<>();
        FileStatus[] entries = fs.listStatus(root);
        Arrays.sort(entries, Comparator.comparing(f -> f.getPath().getName()));
        for (FileStatus f : entries) {
            if (f.isDirectory()) {
                out.addAll(filesUnder(fs, f.getPath()));
            } else {
                out.add(f.getPath());
            }
        }
        return out;
    }

    private static Path qualified(String output, Configuration conf) throws IOException {
        String local = InputRefs.localPath(output);
        if (local != null) {
            return new Path(java.nio.file.Path.of(local).toAbsolutePath().normalize().toUri());
        }
        Path p = new Path(URI.create(output));
        return p.getFileSystem(conf).makeQualified(p);
    }

    /** The file system of {@code p}; for local files the raw one, which writes no {@code .crc} files beside. */
    static FileSystem fileSystem(Path p, Configuration conf) throws IOException {
        FileSystem fs = p.getFileSystem(conf);
        return fs instanceof org.apache.hadoop.fs.LocalFileSystem local ? local.getRawFileSystem() : fs;
    }
}
