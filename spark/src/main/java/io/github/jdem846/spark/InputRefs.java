package io.github.jdem846.spark;

import java.io.IOException;
import java.io.Serializable;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.apache.hadoop.conf.Configuration;
import org.apache.hadoop.fs.FileStatus;
import org.apache.hadoop.fs.FileSystem;
import org.apache.hadoop.fs.Path;
import org.apache.spark.SparkFiles;
import org.apache.spark.api.java.JavaSparkContext;

/**
 * Where each process finds the DEM files. A local path (or {@code file:} URI) is read in place, so on a cluster it
 * must name a file system every executor mounts at the same path; a path of another Hadoop file system
 * ({@code hdfs://}, {@code s3a://}, …; globs and directories allowed) is expanded on the driver into its DEM files,
 * which Spark copies to each executor once ({@link JavaSparkContext#addFile}) with their side files ({@code .hdr},
 * {@code .prj}, {@code .tfw}, {@code .aux.xml}), and which the driver copies for its own reading of headers.
 */
final class InputRefs implements Serializable {

    private static final long serialVersionUID = 1L;

    /** The file extensions taken from a directory, as the CLI takes them. */
    static final Set<String> DEM_EXTENSIONS = Set.of("tif", "tiff", "gtif", "flt", "bil", "hgt", "asc");
    private static final Pattern SCHEME = Pattern.compile("^([a-zA-Z][a-zA-Z0-9+.-]+):(//)?(.*)$");
    private static final List<String> STEM_SIDE_FILES = List.of("hdr", "prj", "tfw");

    /** One FILE argument as given, or one file of a remote argument under the name Spark gives it. */
    private record Ref(String local, String sparkName) implements Serializable {
        private static final long serialVersionUID = 1L;
    }

    private final List<Ref> refs;
    /** The driver's copies of the remote files, by position; null on executors. */
    private final transient List<String> driverFiles;

    private InputRefs(List<Ref> refs, List<String> driverFiles) {
        this.refs = List.copyOf(refs);
        this.driverFiles = driverFiles;
    }

    /**
     * Resolves the FILE arguments on the driver.
     *
     * @param copies a local directory for the driver's copies of remote files
     * @throws IOException naming an argument that matches no file, a remote GDAL VRT, or two remote files of the
     *                     same name
     */
    static InputRefs resolve(List<String> files, JavaSparkContext sc, Configuration conf, java.nio.file.Path copies)
            throws IOException {
        List<Ref> refs = new ArrayList<>();
        List<String> driver = new ArrayList<>();
        Set<String> names = new HashSet<>();
        for (String arg : files) {
            String local = localPath(arg);
            if (local != null) {
                refs.add(new Ref(local, null));
                driver.add(local);
                continue;
            }
            for (FileStatus file : remoteFiles(arg, conf)) {
                String name = file.getPath().getName();
                if (name.toLowerCase(Locale.ROOT).endsWith(".vrt")) {
                    throw new IOException(arg + ": a GDAL VRT is read in place; put it on a file system every "
                            + "executor mounts at the same path, or name its files instead");
                }
                if (!names.add(name)) {
                    throw new IOException(arg + ": two input files are named " + name + "; Spark copies files to "
                            + "the executors by name, so remote inputs need distinct names");
                }
                FileSystem fs = file.getPath().getFileSystem(conf);
                for (Path p : withSideFiles(fs, file.getPath())) {
                    sc.addFile(p.toString());
                    java.nio.file.Path copy = copies.resolve(p.getName());
                    if (!Files.exists(copy)) {
                        fs.copyToLocalFile(false, p, new Path(copy.toUri()), true);
                    }
                }
                refs.add(new Ref(null, name));
                driver.add(copies.resolve(name).toString());
            }
        }
        return new InputRefs(refs, List.copyOf(driver));
    }

    /** @return the files as the driver reads them */
    List<String> driverFiles() {
        if (driverFiles == null) {
            throw new IllegalStateException("the driver's files are not known on an executor");
        }
        return driverFiles;
    }

    /** @return the files as an executor reads them: in place, or Spark's local copies */
    List<String> executorFiles() {
        List<String> out = new ArrayList<>(refs.size());
        for (Ref r : refs) {
            out.add(r.local() != null ? r.local() : SparkFiles.get(r.sparkName()));
        }
        return out;
    }

    /** @return whether every input is read in place */
    boolean allLocal() {
        return refs.stream().allMatch(r -> r.local() != null);
    }

    /** The local path of a local argument (a plain path or a {@code file:} URI); null for another file system. */
    static String localPath(String arg) {
        Matcher m = SCHEME.matcher(arg);
        if (!m.matches() || m.group(1).length() < 2) { // "C:\…" is a drive letter, not a scheme
            return arg;
        }
        if (m.group(1).equalsIgnoreCase("file")) {
            String rest = m.group(3);
            return rest.startsWith("/") ? rest : "/" + rest;
        }
        return null;
    }

    private static List<FileStatus> remoteFiles(String arg, Configuration conf) throws IOException {
        Path pattern = new Path(arg);
        FileSystem fs = pattern.getFileSystem(conf);
        FileStatus[] matches = fs.globStatus(pattern);
        if (matches == null || matches.length == 0) {
            throw new IOException(arg + ": no such file");
        }
        List<FileStatus> out = new ArrayList<>();
        for (FileStatus s : matches) {
            if (s.isDirectory()) {
                FileStatus[] inDir = fs.listStatus(s.getPath());
                Arrays.sort(inDir, Comparator.comparing(f -> f.getPath().getName()));
                int before = out.size();
                for (FileStatus f : inDir) {
                    if (f.isFile() && DEM_EXTENSIONS.contains(extension(f.getPath().getName()))) {
                        out.add(f);
                    }
                }
                if (out.size() == before) {
                    throw new IOException(s.getPath() + ": the directory holds no DEM file (."
                            + String.join(", .", DEM_EXTENSIONS.stream().sorted().toList()) + ")");
                }
            } else {
                out.add(s);
            }
        }
        return out;
    }

    /** The file and those of its side files that exist. */
    private static List<Path> withSideFiles(FileSystem fs, Path file) throws IOException {
        List<Path> out = new ArrayList<>();
        out.add(file);
        String name = file.getName();
        int dot = name.lastIndexOf('.');
        String stem = dot > 0 ? name.substring(0, dot) : name;
        for (String ext : STEM_SIDE_FILES) {
            Path side = new Path(file.getParent(), stem + "." + ext);
            if (!side.getName().equals(name) && fs.exists(side)) {
                out.add(side);
            }
        }
        Path aux = new Path(file.getParent(), name + ".aux.xml");
        if (fs.exists(aux)) {
            out.add(aux);
        }
        return out;
    }

    private static String extension(String name) {
        int dot = name.lastIndexOf('.');
        return dot < 0 ? "" : name.substring(dot + 1).toLowerCase(Locale.ROOT);
    }
}
