package io.github.jdem846.io.source;

import io.github.jdem846.internal.SafeXml;
import java.io.StringReader;
import java.util.List;
import java.util.Locale;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;
import org.xml.sax.InputSource;

/**
 * A linear unpacking of stored values, elevation = raw × {@code scale} + {@code offset}, as GDAL records it for a
 * band whose integers hold e.g. decimetres (the {@code SCALE} and {@code OFFSET} items of the GDAL_METADATA TIFF
 * tag). The no-data value applies to the raw values, before unpacking, as in GDAL.
 */
public record ValueScale(double scale, double offset) {

    /** Elevation = raw value. */
    public static final ValueScale IDENTITY = new ValueScale(1, 0);

    public boolean isIdentity() {
        return scale == 1 && offset == 0;
    }

    /** Unpacks {@code values[0..n)} in place (NaN stays NaN). */
    public void apply(float[] values, int n) {
        for (int i = 0; i < n; i++) {
            values[i] = (float) (values[i] * scale + offset);
        }
    }

    /**
     * The scale and offset of band 1 (sample 0) in the XML of a GDAL_METADATA tag, or {@link #IDENTITY} when the
     * text names neither. A value that is not a finite number, or a scale of 0, is ignored with a notice. Text
     * that does not contain the words "scale" or "offset" is not parsed at all (GDAL writes this tag for
     * statistics and other items too, and an XML parser costs ~50 ms to load on a cold JVM).
     */
    public static ValueScale fromGdalMetadata(String xml, List<String> notices) {
        if (xml == null || !mentionsScaleOrOffset(xml)) {
            return IDENTITY;
        }
        double scale = 1;
        double offset = 0;
        try {
            NodeList items = SafeXml.newBuilder().parse(new InputSource(new StringReader(xml.strip())))
                    .getElementsByTagName("Item");
            for (int i = 0; i < items.getLength(); i++) {
                Element item = (Element) items.item(i);
                String role = item.getAttribute("role").toLowerCase(Locale.ROOT);
                String sample = item.getAttribute("sample");
                if (!(role.equals("scale") || role.equals("offset")) || !(sample.isEmpty() || sample.equals("0"))) {
                    continue;
                }
                String text = item.getTextContent().strip();
                double v;
                try {
                    v = Double.parseDouble(text);
                } catch (NumberFormatException e) {
                    v = Double.NaN;
                }
                if (!Double.isFinite(v) || (role.equals("scale") && v == 0)) {
                    notices.add("GDAL " + role + " '" + text + "' is not usable and was ignored");
                } else if (role.equals("scale")) {
                    scale = v;
                } else {
                    offset = v;
                }
            }
        } catch (Exception e) {
            notices.add("the GDAL_METADATA tag is not readable XML and was ignored");
            return IDENTITY;
        }
        ValueScale s = new ValueScale(scale, offset);
        if (!s.isIdentity()) {
            notices.add("stored values are unpacked as elevation = raw × " + fmt(scale) + " + " + fmt(offset)
                    + " (the file's GDAL scale and offset; no-data applies to the raw values)");
        }
        return s;
    }


    private static boolean mentionsScaleOrOffset(String xml) {
        String lower = xml.toLowerCase(Locale.ROOT);
        return lower.contains("scale") || lower.contains("offset");
    }

    private static String fmt(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
