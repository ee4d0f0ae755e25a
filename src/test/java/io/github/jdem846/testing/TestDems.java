package io.github.jdem846.testing;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;

/**
 * Test fixtures: the real DEMs of {@code testdata/dem/}, loaded by a deliberately minimal GridFloat parser that is
 * independent of the production readers (so stage tests do not depend on reader code, and reader tests have a
 * second opinion). The CRS of each dataset is set from testdata/PROVENANCE.md, not from its .prj.
 */
public final class TestDems {

    /** Repository-relative folder with the dataset copies. */
    public static final Path DEM_DIR = Path.of("testdata", "dem");

    public static final String BIG_TUJUNGA = "bigtujunga_srtm30m_utm11n";
    public static final String JACKSBORO = "jacksboro_srtm3s_wgs84";
    public static final String LUXEMBOURG = "luxembourg_srtm30s_wgs84";
    public static final String VANCOUVER = "vancouver-island_topobathy_2min_mercator";
    public static final String VOLCANO = "maungawhau-volcano_10m_nztm-approx";

    private TestDems() {
    }

    /** Loads {@code testdata/dem/<name>.flt/.hdr}. */
    public static Dem load(String name) {
        try {
            Map<String, String> hdr = new HashMap<>();
            for (String line : Files.readAllLines(DEM_DIR.resolve(name + ".hdr"))) {
                String[] kv = line.trim().split("\\s+");
                if (kv.length == 2) {
                    hdr.put(kv[0].toLowerCase(Locale.ROOT), kv[1]);
                }
            }
            int cols = Integer.parseInt(hdr.get("ncols"));
            int rows = Integer.parseInt(hdr.get("nrows"));
            double cs = Double.parseDouble(hdr.get("cellsize"));
            double xll = Double.parseDouble(hdr.get("xllcorner"));
            double yll = Double.parseDouble(hdr.get("yllcorner"));
            double nodata = Double.parseDouble(hdr.get("nodata_value"));
            ByteBuffer buf = ByteBuffer.wrap(Files.readAllBytes(DEM_DIR.resolve(name + ".flt")))
                    .order(ByteOrder.LITTLE_ENDIAN);
            float[] v = new float[cols * rows];
            buf.asFloatBuffer().get(v);
            GridGeometry g = new GridGeometry(cols, rows, xll, yll + rows * cs, cs, cs, crsOf(name),
                    PixelAnchor.CORNER);
            return new Dem(v, g, nodata);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static CrsInfo crsOf(String name) {
        return switch (name) {
            case BIG_TUJUNGA -> CrsInfo.projected("WGS 84 / UTM zone 11N", 32611, 1.0, Ellipsoid.WGS84);
            case VANCOUVER -> CrsInfo.projected("WGS 84 / Pseudo-Mercator", 3857, 1.0, Ellipsoid.WGS84);
            case VOLCANO -> CrsInfo.projected("NZGD2000 / New Zealand Transverse Mercator 2000", 2193, 1.0,
                    Ellipsoid.GRS80);
            default -> CrsInfo.geographic("WGS 84", 4326, Ellipsoid.WGS84);
        };
    }
}
