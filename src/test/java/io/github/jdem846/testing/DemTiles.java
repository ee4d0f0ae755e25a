package io.github.jdem846.testing;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import java.io.IOException;
import java.math.BigDecimal;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Cuts a real DEM into tiles written as files, for mosaic tests: GridFloat ({@code .flt}/{@code .hdr}, optionally
 * a {@code .prj}) or float32 GeoTIFF (through {@link TinyTiff}, with GeoKeys naming an EPSG code). No-data (NaN
 * in the grid) is written as −9999 and declared so. A GeoTIFF tile's tie point is the whole grid's corner moved by
 * whole cells, exactly as {@link GridGeometry#window} computes it.
 */
public final class DemTiles {

    /** No-data written in the tiles. */
    public static final float NO_DATA = -9999f;

    /** Columns {@code [col, col + width)} and rows {@code [row, row + height)} of the whole grid. */
    public record Cut(int col, int row, int width, int height) {
    }

    private DemTiles() {
    }

    /**
     * Four tiles split at column {@code cx} and row {@code ry}, the western and northern ones reaching
     * {@code overlap} cells past the split (SRTM tiles share one row and one column): north-west, north-east,
     * south-west, south-east.
     */
    public static List<Cut> quarters(int width, int height, int cx, int ry, int overlap) {
        return List.of(new Cut(0, 0, cx + overlap, ry + overlap), new Cut(cx, 0, width - cx, ry + overlap),
                new Cut(0, ry, cx + overlap, height - ry), new Cut(cx, ry, width - cx, height - ry));
    }

    /** The cells of {@code cut} of {@code whole}, NaN as {@link #NO_DATA}. */
    public static float[] cells(Dem whole, Cut cut) {
        float[] out = new float[cut.width() * cut.height()];
        for (int r = 0; r < cut.height(); r++) {
            for (int c = 0; c < cut.width(); c++) {
                float v = whole.get(cut.col() + c, cut.row() + r);
                out[r * cut.width() + c] = Float.isNaN(v) ? NO_DATA : v;
            }
        }
        return out;
    }

    /**
     * Writes each cut as {@code <name>_<i>.flt} + {@code .hdr} (LSBFIRST, NODATA_value −9999) and, when
     * {@code prj} is not null, a copy of it as {@code .prj}.
     *
     * @return the {@code .flt} files, in the order of {@code cuts}
     */
    public static List<Path> gridFloat(Dem whole, List<Cut> cuts, Path dir, String name, Path prj)
            throws IOException {
        List<Path> files = new ArrayList<>();
        for (int i = 0; i < cuts.size(); i++) {
            Path flt = dir.resolve(name + "_" + i + ".flt");
            writeGridFloat(flt, cells(whole, cuts.get(i)), whole.geometry(), cuts.get(i), prj);
            files.add(flt);
        }
        return files;
    }

    /** Writes {@code values} as the GridFloat of {@code cut} of a grid of geometry {@code g}. */
    public static void writeGridFloat(Path flt, float[] values, GridGeometry g, Cut cut, Path prj)
            throws IOException {
        ByteBuffer b = ByteBuffer.allocate(values.length * 4).order(ByteOrder.LITTLE_ENDIAN);
        b.asFloatBuffer().put(values);
        Files.write(flt, b.array());
        double xll = g.originX() + cut.col() * g.cellWidth();
        double yll = g.originY() - (cut.row() + cut.height()) * g.cellHeight();
        Files.writeString(sibling(flt, "hdr"), "ncols " + cut.width() + "\nnrows " + cut.height()
                + "\nxllcorner " + plain(xll) + "\nyllcorner " + plain(yll) + "\ncellsize " + plain(g.cellWidth())
                + "\nNODATA_value -9999\nbyteorder LSBFIRST\n");
        if (prj != null) {
            Files.copy(prj, sibling(flt, "prj"));
        }
    }

    /**
     * Writes each cut as {@code <name>_<i>.tif}, float32 in one strip, with ModelPixelScale, ModelTiepoint,
     * GeoKeys (EPSG {@code epsg}, geographic or projected, PixelIsArea) and GDAL_NODATA −9999.
     *
     * @return the files, in the order of {@code cuts}
     */
    public static List<Path> geoTiff(Dem whole, List<Cut> cuts, Path dir, String name, int epsg,
                                     boolean geographic) throws IOException {
        List<Path> files = new ArrayList<>();
        for (int i = 0; i < cuts.size(); i++) {
            Path tif = dir.resolve(name + "_" + i + ".tif");
            Cut cut = cuts.get(i);
            GridGeometry g = whole.geometry().window(cut.col(), cut.row(), cut.width(), cut.height());
            writeGeoTiff(tif, cells(whole, cut), cut.width(), cut.height(), g.originX(), g.originY(),
                    g.cellWidth(), g.cellHeight(), epsg, geographic);
            files.add(tif);
        }
        return files;
    }

    /** A float32 GeoTIFF of {@code values} with its corner at ({@code x}, {@code y}). */
    public static void writeGeoTiff(Path tif, float[] values, int width, int height, double x, double y,
                                    double cellWidth, double cellHeight, int epsg, boolean geographic)
            throws IOException {
        ByteBuffer b = ByteBuffer.allocate(values.length * 4).order(ByteOrder.LITTLE_ENDIAN);
        b.asFloatBuffer().put(values);
        TinyTiff t = TinyTiff.int16(width, height).data(b.array()).set(258, TinyTiff.SHORT, 32)
                .set(339, TinyTiff.SHORT, 3).set(279, TinyTiff.LONG, b.capacity())
                .georeferenced(x, y, cellWidth, cellHeight)
                .set(34735, TinyTiff.SHORT, 1, 1, 0, 3, 1024, 0, 1, geographic ? 2 : 1, 1025, 0, 1, 1,
                        geographic ? 2048 : 3072, 0, 1, epsg)
                .ascii(42113, "-9999");
        Files.write(tif, t.bytes());
    }

    /** {@code file} with another extension. */
    public static Path sibling(Path file, String ext) {
        String n = file.getFileName().toString();
        return file.resolveSibling(n.substring(0, n.lastIndexOf('.') + 1) + ext);
    }

    /** The shortest decimal that reads back as {@code v}, without an exponent. */
    public static String plain(double v) {
        return new BigDecimal(Double.toString(v)).toPlainString();
    }
}
