<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DataFileName name="head.ply"/>
 </DocumentData>
 <point x="1.5" y="2" z="30" active="1" name="nose_tip"/>
 <point x="40" y="30" z="5" active="1" name="left_eye_outer"/>
 <point x="-40" y="30" z="5.25" active="1" name="right_eye_outer"/>
 <point x="0" y="0" z="0" active="0" name="chin"/>
</PickedPoints>
