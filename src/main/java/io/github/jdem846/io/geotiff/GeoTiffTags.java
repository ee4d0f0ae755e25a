package io.github.jdem846.io.geotiff;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.internal.GeoKeys;
import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.SampleType;
import io.github.jdem846.io.esri.EsriGridLayout;
import io.github.jdem846.io.esri.SidecarCrs;
import io.github.jdem846.io.source.ReaderGeometry;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * What a GeoTIFF's tags say before any pixel is decoded: whether its compression can be decoded, its sample type,
 * its grid (ModelPixelScale + ModelTiepoint or ModelTransformation, PixelIsArea or PixelIsPoint, the CRS from the
 * GeoKeys) and its GDAL no-data value. Each refusal names the file and the tag.
 */
final class GeoTiffTags {

    private GeoTiffTags() {
    }

    /** TIFF compression codes TwelveMonkeys decodes for DEMs, with their names. */
    static final java.util.Map<Integer, String> DECODED_COMPRESSIONS = java.util.Map.of(
            1, "none", 5, "LZW", 8, "Deflate", 32946, "Deflate", 32773, "PackBits", 6, "old-style JPEG",
            7, "JPEG");

    /** Refuses compressions we cannot decode before any pixel is read, naming the compression and a remedy. */
    static void checkCompression(Path tif, TiffFields fields) throws DemFormatException {
        int code = fields.intValue(TiffFields.COMPRESSION, 1);
        if (DECODED_COMPRESSIONS.containsKey(code)) {
            return;
        }
        String name = switch (code) {
            case 50000 -> "ZSTD";
            case 34925 -> "LZMA";
            case 50001 -> "WebP";
            case 34887 -> "LERC";
            default -> "code " + code;
        };
        boolean floating = fields.has(TiffFields.SAMPLE_FORMAT) && fields.longs(TiffFields.SAMPLE_FORMAT)[0] == 3;
        throw new DemFormatException(tif, name + " compression (TIFF tag 259 = " + code + ") is not supported; "
                + "supported: none, LZW, Deflate, PackBits, JPEG. Re-encode it, e.g. gdal_translate -co "
                + "COMPRESS=DEFLATE -co PREDICTOR=" + (floating ? 3 : 2) + " in.tif out.tif");
    }

    /** The sample type from BitsPerSample and SampleFormat, refusing what a DEM reader cannot decode. */
    static SampleType sampleType(Path tif, TiffFields fields) throws DemFormatException {
        long[] bits = fields.has(TiffFields.BITS_PER_SAMPLE) ? fields.longs(TiffFields.BITS_PER_SAMPLE)
                : new long[] {1};
        long[] formats = fields.has(TiffFields.SAMPLE_FORMAT) ? fields.longs(TiffFields.SAMPLE_FORMAT)
                : new long[] {1};
        int b = (int) bits[0];
        int f = (int) formats[0];
        SampleType t = switch (f) {
            case 1 -> b == 8 ? SampleType.UINT8 : b == 16 ? SampleType.UINT16 : b == 32 ? SampleType.UINT32 : null;
            case 2 -> b == 8 ? SampleType.INT8 : b == 16 ? SampleType.INT16 : b == 32 ? SampleType.INT32 : null;
            case 3 -> b == 32 ? SampleType.FLOAT32 : b == 64 ? SampleType.FLOAT64 : null;
            default -> null;
        };
        if (t == null) {
            String kind = switch (f) {
                case 1 -> "unsigned integer";
                case 2 -> "signed integer";
                case 3 -> "floating point";
                case 4 -> "undefined";
                case 5 -> "complex integer";
                case 6 -> "complex floating point";
                default -> "SampleFormat " + f;
            };
            throw new DemFormatException(tif, "unsupported sample format: " + b + "-bit " + kind + " (SampleFormat "
                    + f + "); elevations must be 8/16/32-bit signed or unsigned integers or 32/64-bit floats");
        }
        return t;
    }

    /** Grid geometry from ModelTransformation or ModelTiepoint + ModelPixelScale, and the GeoKeys. */
    static GridGeometry geometry(Path tif, TiffFields fields, int width, int height, List<String> notices)
            throws DemFormatException {
        GeoKeyReader keys = GeoKeyReader.empty();
        if (fields.has(TiffFields.GEO_KEY_DIRECTORY)) {
            try {
                keys = GeoKeyReader.parse(fields.longs(TiffFields.GEO_KEY_DIRECTORY),
                        fields.has(TiffFields.GEO_DOUBLE_PARAMS) ? fields.doubles(TiffFields.GEO_DOUBLE_PARAMS) : null,
                        fields.ascii(TiffFields.GEO_ASCII_PARAMS));
            } catch (IllegalArgumentException e) {
                notices.add("GeoKeys ignored: " + e.getMessage());
            }
        }
        double originX;
        double originY;
        double cellW;
        double cellH;
        boolean georeferenced = true;
        String source; // named in messages
        if (fields.has(TiffFields.MODEL_TRANSFORMATION)) {
            source = "ModelTransformation (TIFF tag " + TiffFields.MODEL_TRANSFORMATION + ")";
            double[] m = fields.doubles(TiffFields.MODEL_TRANSFORMATION);
            if (m.length < 8) {
                throw new DemFormatException(tif, "ModelTransformationTag has " + m.length + " values, not 16");
            }
            if (m[1] != 0 || m[4] != 0) {
                throw new DemFormatException(tif, "the grid is rotated or sheared (ModelTransformation row/column"
                        + " terms " + m[1] + ", " + m[4] + "); only north-up grids are read: warp it first, e.g."
                        + " gdalwarp");
            }
            if (!(m[0] > 0) || !(m[5] < 0)) {
                throw new DemFormatException(tif, "the grid is flipped (ModelTransformation scales " + m[0] + ", "
                        + m[5] + "); only north-up grids with columns going east are read");
            }
            cellW = m[0];
            cellH = -m[5];
            originX = m[3];
            originY = m[7];
        } else if (fields.has(TiffFields.MODEL_TIEPOINT) && fields.has(TiffFields.MODEL_PIXEL_SCALE)) {
            source = "ModelTiepoint and ModelPixelScale (TIFF tags " + TiffFields.MODEL_TIEPOINT + ", "
                    + TiffFields.MODEL_PIXEL_SCALE + ")";
            double[] t = fields.doubles(TiffFields.MODEL_TIEPOINT);
            double[] s = fields.doubles(TiffFields.MODEL_PIXEL_SCALE);
            if (t.length < 6 || s.length < 2) {
                throw new DemFormatException(tif, "ModelTiepoint/ModelPixelScale have too few values ("
                        + t.length + ", " + s.length + ")");
            }
            if (t.length > 6) {
                notices.add("the file has " + t.length / 6 + " tie points; the first is used with the pixel scale");
            }
            if (!(s[0] > 0) || !(s[1] > 0)) {
                throw new DemFormatException(tif, "ModelPixelScale is " + s[0] + ", " + s[1]
                        + "; both must be positive (north-up grid)");
            }
            cellW = s[0];
            cellH = s[1];
            originX = t[3] - t[0] * cellW;
            originY = t[4] + t[1] * cellH;
        } else {
            if (fields.has(TiffFields.MODEL_TIEPOINT)) {
                throw new DemFormatException(tif, "the file is georeferenced by tie points (ground control points)"
                        + " without a pixel scale; warp it first, e.g. gdalwarp");
            }
            notices.add("no georeferencing (no ModelPixelScale/ModelTiepoint/ModelTransformation): cells are"
                    + " 1 × 1 unit with the origin at the north-west corner of row 0");
            georeferenced = false;
            source = "the image size (no georeferencing)";
            cellW = 1;
            cellH = 1;
            originX = 0;
            originY = height;
        }
        PixelAnchor anchor = PixelAnchor.CORNER;
        if (keys.code(GeoKeys.GT_RASTER_TYPE).orElse(1) == 2) {
            // PixelIsPoint: the tie point names the centre of the cell; move to its outer corner.
            anchor = PixelAnchor.CENTER;
            originX -= cellW / 2;
            originY += cellH / 2;
        }
        // each value can be sane and the grid still not: 1e308 × rows overflows, 1e-300 cells at 500000 collapse
        ReaderGeometry.check(tif, source, width, height, originX, originY, cellW, cellH);
        CrsInfo crs;
        if (!keys.isEmpty()) {
            crs = GeoTiffCrs.resolve(keys, notices);
        } else if (georeferenced) {
            crs = SidecarCrs.assumeFromExtent(new EsriGridLayout(width, height, originX, originY, cellW, cellH,
                    anchor), "no GeoKeys", notices);
        } else {
            crs = CrsInfo.UNKNOWN;
        }
        return ReaderGeometry.of(tif, source, width, height, originX, originY, cellW, cellH, crs, anchor);
    }

    /** GDAL_NODATA: a number or "nan"; null when absent. */
    static Double noData(TiffFields fields, List<String> notices) {
        String text = fields.ascii(TiffFields.GDAL_NODATA);
        if (text == null) {
            return null;
        }
        String t = text.strip().toLowerCase(Locale.ROOT);
        if (t.isEmpty()) {
            return null;
        }
        if (t.equals("nan") || t.equals("-nan")) {
            return Double.NaN;
        }
        try {
            return Double.parseDouble(t);
        } catch (NumberFormatException e) {
            notices.add("GDAL_NODATA '" + text.strip() + "' is not a number and was ignored");
            return null;
        }
    }
}
