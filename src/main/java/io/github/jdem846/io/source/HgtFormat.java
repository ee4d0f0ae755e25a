package io.github.jdem846.io.source;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.io.DemFormat;
import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.SampleType;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import java.io.IOException;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * SRTM height tiles ({@code N34W118.hgt}): a square of big-endian int16 rows from north to south, 1201 × 1201
 * (3″) or 3601 × 3601 (1″) samples, −32768 = no-data, WGS 84. The name gives the latitude and longitude of the
 * centre of the south-west sample: samples are points on whole-degree lines (PixelIsPoint), so the grid's outer
 * corner is half a cell outside the degree square.
 */
public final class HgtFormat {

    private static final Pattern NAME = Pattern.compile("([NS])(\\d{1,2})([EW])(\\d{1,3}).*\\.HGT");

    private HgtFormat() {
    }

    public static RasterSource open(Path hgt) throws IOException {
        String name = hgt.getFileName().toString().toUpperCase(Locale.ROOT);
        Matcher m = NAME.matcher(name);
        if (!m.matches()) {
            throw new DemFormatException(hgt, "an SRTM .hgt file must be named after its south-west corner, e.g."
                    + " N34W118.hgt, to give its position");
        }
        int lat = Integer.parseInt(m.group(2)) * (m.group(1).equals("S") ? -1 : 1);
        int lon = Integer.parseInt(m.group(4)) * (m.group(3).equals("W") ? -1 : 1);
        if (Math.abs(lat) > 89 || Math.abs(lon) > 180) {
            throw new DemFormatException(hgt, "the name gives latitude " + lat + ", longitude " + lon
                    + ", outside −89…89 and −180…180");
        }
        long size = Files.size(hgt);
        int n;
        if (size == 1201L * 1201 * 2) {
            n = 1201;
        } else if (size == 3601L * 3601 * 2) {
            n = 3601;
        } else {
            throw new DemFormatException(hgt, "is " + size + " bytes; an SRTM tile has 1201 × 1201 × 2 = "
                    + (1201L * 1201 * 2) + " (3″) or 3601 × 3601 × 2 = " + (3601L * 3601 * 2) + " (1″) bytes");
        }
        double cell = 1.0 / (n - 1);
        CrsInfo crs = CrsInfo.WGS84;
        GridGeometry g = new GridGeometry(n, n, lon - cell / 2, lat + 1 + cell / 2, cell, cell, crs,
                PixelAnchor.CENTER);
        DemInfo info = new DemInfo(hgt.toString(), DemFormat.SRTM_HGT, SampleType.INT16, 1, g, -32768.0, List.of());
        return new RawRasterSource(info, hgt, 0, (long) n * 2, SampleType.INT16, ByteOrder.BIG_ENDIAN);
    }
}
