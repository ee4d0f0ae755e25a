package io.github.jdem846.bench;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.testing.SyntheticDems;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Locale;

/**
 * A large DEM of real elevations for benchmarks: a real DEM mirror-tiled to {@code n × n} cells. Tile (i, j) (i
 * counts columns of tiles, j rows) is the source flipped east–west when i is odd and north–south when j is odd, so
 * every tile edge is a reflection and the surface is continuous (no cliffs at the seams). <b>The terrain repeats</b>
 * with a period of twice the source's size; the elevations, cell size and CRS are the source's, tile (0, 0) is the
 * source itself in place (same north-west corner), and no-data cells stay no-data.
 *
 * <p>By default the source is Big Tujunga, SRTM 30 m in UTM 11N (1197×643, testdata/PROVENANCE.md): steep real
 * mountains, where about two thirds of the cells are in shadow at sun elevation 5°, unlike {@link FractalDem}.
 *
 * <pre>java -cp target/benchmarks.jar io.github.jdem846.bench.MirroredDem 4000 [SOURCE.flt] /tmp/mirrored4000</pre>
 * writes {@code /tmp/mirrored4000.flt}, {@code .hdr} and {@code .prj} (GridFloat, float32; the {@code .prj} is a
 * copy of the source's).
 */
public final class MirroredDem {

    /** The default source, relative to the worktree root. */
    public static final Path BIG_TUJUNGA = Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.flt");

    /** Written for no-data cells. */
    private static final float NO_DATA = -9999f;

    private MirroredDem() {
    }

    /** {@code source} mirror-tiled to {@code n × n} in memory ({@link SyntheticDems#mirrored}). */
    public static Dem mirrored(Dem source, int n) {
        return SyntheticDems.mirrored(source, n, n);
    }

    /** Big Tujunga ({@link #BIG_TUJUNGA}) mirror-tiled to {@code n × n}. */
    public static Dem bigTujunga(int n) throws IOException {
        return mirrored(DemReader.read(BIG_TUJUNGA), n);
    }

    /** Writes {@code source} mirror-tiled to {@code n × n} as {@code base}.flt/.hdr/.prj. */
    public static void writeGridFloat(Path source, int n, Path base) throws IOException {
        Path prj = withExtension(source, ".prj");
        if (!Files.isRegularFile(prj)) {
            throw new IOException(source + ": no " + prj.getFileName() + " next to it; MirroredDem copies the source's"
                    + " .prj, so give a GridFloat/BIL/ASCII grid with its .prj");
        }
        Dem dem = DemReader.read(source);
        GridGeometry g = dem.geometry();
        if (g.cellWidth() != g.cellHeight()) {
            throw new IOException(source + ": cells are " + g.cellWidth() + " × " + g.cellHeight()
                    + "; a GridFloat header needs square cells");
        }
        ByteBuffer row = ByteBuffer.allocate(n * 4).order(ByteOrder.LITTLE_ENDIAN);
        try (OutputStream out = Files.newOutputStream(Path.of(base + ".flt"))) {
            for (int y = 0; y < n; y++) {
                int sy = SyntheticDems.mirroredIndex(y, dem.height());
                row.clear();
                for (int x = 0; x < n; x++) {
                    float z = dem.get(SyntheticDems.mirroredIndex(x, dem.width()), sy);
                    row.putFloat(Float.isNaN(z) ? NO_DATA : z);
                }
                out.write(row.array(), 0, row.position());
            }
        }
        String hdr = String.format(Locale.ROOT, "ncols %d\nnrows %d\nxllcorner %s\nyllcorner %s\ncellsize %s\n"
                        + "NODATA_value %s\nbyteorder LSBFIRST\n", n, n, g.originX(), g.originY() - n * g.cellHeight(),
                g.cellWidth(), NO_DATA);
        Files.writeString(Path.of(base + ".hdr"), hdr, StandardCharsets.US_ASCII);
        Files.copy(prj, Path.of(base + ".prj"), StandardCopyOption.REPLACE_EXISTING);
    }

    /** {@code file} with its extension (if any) replaced by {@code extension}. */
    private static Path withExtension(Path file, String extension) {
        String name = file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return file.resolveSibling((dot > 0 ? name.substring(0, dot) : name) + extension);
    }

    /** Usage: {@code MirroredDem N [SOURCE] OUTPUT_BASE}; SOURCE defaults to {@link #BIG_TUJUNGA}. */
    public static void main(String[] args) throws IOException {
        if (args.length < 2 || args.length > 3) {
            System.err.println("usage: MirroredDem N [SOURCE_DEM] OUTPUT_BASE   (writes OUTPUT_BASE.flt/.hdr/.prj;"
                    + " SOURCE_DEM defaults to " + BIG_TUJUNGA + ")");
            System.exit(2);
        }
        int n = Integer.parseInt(args[0]);
        Path source = args.length == 3 ? Path.of(args[1]) : BIG_TUJUNGA;
        writeGridFloat(source, n, Path.of(args[args.length - 1]));
    }
}
