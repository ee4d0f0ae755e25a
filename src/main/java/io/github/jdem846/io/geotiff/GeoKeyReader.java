package io.github.jdem846.io.geotiff;

import static io.github.jdem846.internal.GeoKeys.*;

import io.github.jdem846.internal.GeoKeys;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

/**
 * The GeoKeys of a GeoTIFF (GeoKeyDirectoryTag 34735 with GeoDoubleParamsTag 34736 and GeoAsciiParamsTag 34737;
 * OGC GeoTIFF 1.1, section 7.1.3), parsed by hand from the TIFF fields; {@code output.GeoKeyWriter} is its counterpart
 * for writing.
 */
final class GeoKeyReader {


    private final Map<Integer, Object> keys; // Integer, double[] or String

    private GeoKeyReader(Map<Integer, Object> keys) {
        this.keys = keys;
    }

    /** An empty directory (no GeoKeys). */
    static GeoKeyReader empty() {
        return new GeoKeyReader(Map.of());
    }

    /**
     * Parses the directory.
     *
     * @throws IllegalArgumentException when it is malformed (the message says how)
     */
    static GeoKeyReader parse(long[] dir, double[] doubles, String ascii) {
        if (dir.length < 4) {
            throw new IllegalArgumentException("the GeoKey directory has " + dir.length + " values, fewer than its"
                    + " 4-value header");
        }
        int count = (int) dir[3];
        if (dir.length < 4 + 4L * count) {
            throw new IllegalArgumentException("the GeoKey directory announces " + count + " keys but holds "
                    + (dir.length - 4) / 4);
        }
        Map<Integer, Object> map = new HashMap<>();
        for (int i = 0; i < count; i++) {
            int at = 4 + 4 * i;
            int id = (int) dir[at];
            int location = (int) dir[at + 1];
            int n = (int) dir[at + 2];
            int value = (int) dir[at + 3];
            if (location == 0) {
                map.put(id, value);
            } else if (location == TiffFields.GEO_DOUBLE_PARAMS) {
                if (doubles == null || value < 0 || value + n > doubles.length) {
                    throw new IllegalArgumentException("GeoKey " + id + " points outside GeoDoubleParams");
                }
                double[] d = new double[n];
                System.arraycopy(doubles, value, d, 0, n);
                map.put(id, d);
            } else if (location == TiffFields.GEO_ASCII_PARAMS) {
                if (ascii == null || value < 0 || value + n > ascii.length()) {
                    throw new IllegalArgumentException("GeoKey " + id + " points outside GeoAsciiParams");
                }
                String s = ascii.substring(value, value + n);
                if (s.endsWith("|")) {
                    s = s.substring(0, s.length() - 1);
                }
                map.put(id, s.strip());
            }
        }
        return new GeoKeyReader(map);
    }

    boolean isEmpty() {
        return keys.isEmpty();
    }

    boolean has(int key) {
        return keys.containsKey(key);
    }

    /** A SHORT key. */
    Optional<Integer> code(int key) {
        return keys.get(key) instanceof Integer i ? Optional.of(i) : Optional.empty();
    }

    /** A DOUBLE key's first value. */
    Optional<Double> number(int key) {
        return keys.get(key) instanceof double[] d && d.length > 0 ? Optional.of(d[0]) : Optional.empty();
    }

    /** An ASCII key, without GDAL's "PCS Name = " style prefixes. */
    Optional<String> text(int key) {
        if (!(keys.get(key) instanceof String s) || s.isBlank()) {
            return Optional.empty();
        }
        String t = s;
        for (String prefix : new String[] {"PCS Name = ", "GCS Name = "}) {
            if (t.startsWith(prefix)) {
                t = t.substring(prefix.length());
            }
        }
        int bar = t.indexOf('|');
        if (bar >= 0) {
            t = t.substring(0, bar);
        }
        t = t.strip();
        return t.isEmpty() || t.equalsIgnoreCase("unknown") ? Optional.empty() : Optional.of(t);
    }
}
