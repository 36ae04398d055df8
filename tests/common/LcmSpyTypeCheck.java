// Resolves LCM fingerprints to classes exactly as lcm-spy does (LCMTypeDatabase
// scans the class path). Prints "<fingerprint> <class name or MISSING>" per argument.
public class LcmSpyTypeCheck {
  public static void main(String[] args) {
    lcm.spy.LCMTypeDatabase db = new lcm.spy.LCMTypeDatabase();
    for (String arg : args) {
      long fingerprint = Long.parseLong(arg);
      Class<?> cls = db.getClassByFingerprint(fingerprint);
      System.out.println(arg + " " + (cls == null ? "MISSING" : cls.getName()));
    }
  }
}
