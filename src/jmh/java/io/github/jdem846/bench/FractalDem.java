package io.github.jdem846.bench;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.SplittableRandom;

/**
 * A reproducible fractal DEM for benchmarks and the accuracy study: diamond-square (roughness 0.5, relief about
 * ±1000 m around 1500 m) on the next power of two, cropped to {@code size × size}, 30 m cells in UTM zone 11N.
 * The same size and seed always give the same elevations, bit for bit.
 *
 * <pre>java -cp target/benchmarks.jar io.github.jdem846.bench.FractalDem 4000 846 /tmp/fractal4000</pre>
 * writes {@code /tmp/fractal4000.flt}, {@code .hdr} and {@code .prj} (GridFloat); {@code gdal_translate} turns it
 * into a GeoTIFF for peers that want one.
 */
public final class FractalDem {

    /** Cell size, metres. */
    public static final double CELL_SIZE = 30;
    /** Lower-left corner in UTM 11N (EPSG:32611), metres. */
    public static final double X_LL = 400_000;
    public static final double Y_LL = 3_700_000;

    private FractalDem() {
    }

    /** The elevations, row-major, row 0 = north. */
    public static float[] elevations(int size, long seed) {
        int n = Integer.highestOneBit(Math.max(2, size - 1)) << 1;
        if (n / 2 >= size) {
            n /= 2;
        }
        double[] h = new double[(n + 1) * (n + 1)];
        SplittableRandom rnd = new SplittableRandom(seed);
        double amplitude = 1000;
        for (int step = n; step > 1; step /= 2, amplitude *= 0.5) {
            int half = step / 2;
            for (int y = half; y < n; y += step) {           // diamond: centres of squares
                for (int x = half; x < n; x += step) {
                    double mean = (h[(y - half) * (n + 1) + x - half] + h[(y - half) * (n + 1) + x + half]
                            + h[(y + half) * (n + 1) + x - half] + h[(y + half) * (n + 1) + x + half]) / 4;
                    h[y * (n + 1) + x] = mean + amplitude * (rnd.nextDouble() * 2 - 1);
                }
            }
            for (int y = 0; y <= n; y += half) {               // square: edge midpoints
                for (int x = (y / half) % 2 == 0 ? half : 0; x <= n; x += step) {
                    double sum = 0;
                    int count = 0;
                    if (y >= half) { sum += h[(y - half) * (n + 1) + x]; count++; }
                    if (y + half <= n) { sum += h[(y + half) * (n + 1) + x]; count++; }
                    if (x >= half) { sum += h[y * (n + 1) + x - half]; count++; }
                    if (x + half <= n) { sum += h[y * (n + 1) + x + half]; count++; }
                    h[y * (n + 1) + x] = sum / count + amplitude * (rnd.nextDouble() * 2 - 1);
                }
            }
        }
        float[] v = new float[size * size];
        for (int y = 0; y < size; y++) {
            for (int x = 0; x < size; x++) {
                v[y * size + x] = (float) (1500 + h[y * (n + 1) + x]);
            }
        }
        return v;
    }

    /** The fractal as an in-memory DEM with a metric grid of {@link #CELL_SIZE} (no CRS). */
    public static Dem dem(int size, long seed) {
        return new Dem(elevations(size, seed), GridGeometry.metric(size, size, CELL_SIZE));
    }

    /** Writes {@code base}.flt/.hdr/.prj. */
    public static void writeGridFloat(int size, long seed, Path base) throws IOException {
        float[] v = elevations(size, seed);
        Path flt = Path.of(base + ".flt");
        ByteBuffer row = ByteBuffer.allocate(size * 4).order(ByteOrder.LITTLE_ENDIAN);
        try (OutputStream out = Files.newOutputStream(flt)) {
            for (int y = 0; y < size; y++) {
                row.clear();
                for (int x = 0; x < size; x++) {
                    row.putFloat(v[y * size + x]);
                }
                out.write(row.array(), 0, row.position());
            }
        }
        String hdr = "ncols " + size + "\nnrows " + size + "\nxllcorner " + X_LL + "\nyllcorner " + Y_LL
                + "\ncellsize " + CELL_SIZE + "\nNODATA_value -9999\nbyteorder LSBFIRST\n";
        Files.writeString(Path.of(base + ".hdr"), hdr, StandardCharsets.US_ASCII);
        Files.writeString(Path.of(base + ".prj"), UTM11N_WKT, StandardCharsets.US_ASCII);
    }

    /** Usage: {@code FractalDem SIZE SEED BASE}. */
    public static void main(String[] args) throws IOException {
        if (args.length != 3) {
            System.err.println("usage: FractalDem SIZE SEED OUTPUT_BASE   (writes OUTPUT_BASE.flt/.hdr/.prj)");
            System.exit(2);
        }
        writeGridFloat(Integer.parseInt(args[0]), Long.parseLong(args[1]), Path.of(args[2]));
    }

    private static final String UTM11N_WKT = "PROJCS[\"WGS_1984_UTM_Zone_11N\",GEOGCS[\"GCS_WGS_1984\","
            + "DATUM[\"D_WGS_1984\",SPHEROID[\"WGS_1984\",6378137.0,298.257223563]],PRIMEM[\"Greenwich\",0.0],"
            + "UNIT[\"Degree\",0.0174532925199433]],PROJECTION[\"Transverse_Mercator\"],"
            + "PARAMETER[\"False_Easting\",500000.0],PARAMETER[\"False_Northing\",0.0],"
            + "PARAMETER[\"Central_Meridian\",-117.0],PARAMETER[\"Scale_Factor\",0.9996],"
            + "PARAMETER[\"Latitude_Of_Origin\",0.0],UNIT[\"Meter\",1.0]]";
}
